// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// CellComplex::fromLayout: a complex from its flat lists (the snapshot
// reader's path). A valid layout is checked in bulk and copied list by list;
// a defective one is rebuilt element by element, which names the defect.
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "closed_surface.hpp"
#include "tessella/tissue/cell_complex.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella {

namespace {

std::string id(const char* kind, Index i) { return std::string(kind) + " " + std::to_string(i); }

// The CSR pair of a layout: `count` lists covering the items exactly.
void checkLists(const char* name, std::span<const Index> offsets, std::size_t num_items, std::size_t count) {
  if (offsets.size() != count + 1)
    throw TopologyError(std::string("layout: ") + name + " has " +
                        std::to_string(offsets.empty() ? 0 : offsets.size() - 1) + " lists, not " +
                        std::to_string(count));
  if (offsets[0] != 0 || offsets[count] != num_items)
    throw TopologyError(std::string("layout: the offsets of ") + name + " do not cover its " +
                        std::to_string(num_items) + " items");
  for (std::size_t k = 0; k < count; ++k)
    if (offsets[k + 1] < offsets[k])
      throw TopologyError(std::string("layout: the offsets of ") + name + " decrease at list " + std::to_string(k));
}

template <typename H>
void unpack(std::span<const Index> items, std::vector<Oriented<H>>& out) {
  out.clear();
  for (Index packed : items) out.emplace_back(H(packed >> 1), (packed & 1u) != 0);
}

// True when the element-by-element construction below would accept the
// layout: every check of addEdge / addFace / addVolume and of the region
// lists, run in bulk (in parallel, without building anything). A layout it
// rejects goes the element-by-element way, which throws the first defect's
// located message, so messages do not depend on the path.
bool bulkLayoutValid(const ComplexLayout& L, std::size_t nv, std::size_t ne, std::size_t nf, std::size_t nc) {
  const auto& ev = L.edge_vertices;
  for (Index v : ev)
    if (v >= nv) return false;
  // Built regions in numbering order (counting sort): the edges at each vertex,
  // the faces at each edge, the volumes at each face.
  auto invert = [](std::size_t count, std::size_t num_items, auto itemsOf, std::vector<Index>& offsets,
                   std::vector<Index>& items) {
    offsets.assign(count + 1, 0);
    for (std::size_t k = 0; k < num_items; ++k) itemsOf(k, [&](Index x) { ++offsets[x + 1]; });
    for (std::size_t x = 0; x < count; ++x) offsets[x + 1] += offsets[x];
    items.resize(offsets[count]);
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t k = 0; k < num_items; ++k) itemsOf(k, [&](Index x) { items[fill[x]++] = static_cast<Index>(k); });
  };
  std::vector<Index> star_at, star;
  invert(nv, ne, [&](std::size_t e, auto add) { add(ev[2 * e]); add(ev[2 * e + 1]); }, star_at, star);
  auto other = [&](Index e, Index v) { return ev[2 * e] == v ? ev[2 * e + 1] : ev[2 * e]; };
  bool ok = true;
  const std::int64_t nvs = static_cast<std::int64_t>(nv);
  // Per vertex: no edge to itself, no two edges to one neighbour, and the listed star is the built one.
#pragma omp parallel for schedule(static) reduction(&& : ok)
  for (std::int64_t v = 0; v < nvs; ++v) {
    const Index b = star_at[v], m = star_at[v + 1] - b;
    const Index lb = L.vertex_edge_offsets[v], lm = L.vertex_edge_offsets[v + 1] - lb;
    bool good = lm == m;
    for (Index i = 0; i < m && good; ++i) {
      const Index e = star[b + i], w = other(e, static_cast<Index>(v));
      good = w != static_cast<Index>(v);
      for (Index j = 0; j < i && good; ++j) good = other(star[b + j], static_cast<Index>(v)) != w;
      // The listed star holds e (lists are short: a vertex has a handful of edges).
      bool listed = false;
      for (Index j = 0; j < lm && !listed; ++j) listed = L.vertex_edges[lb + j] == e;
      good = good && listed;
    }
    ok = ok && good;  // (equal sizes, every built edge listed, built edges distinct: the same set)
  }
  if (!ok) return false;
  // Faces: closed loops of live edges, no vertex or edge twice, at least 3 edges.
  const auto& fe = L.face_edges;
  auto tail = [&](Index packed) { return ev[2 * (packed >> 1) + (packed & 1u)]; };
  auto head = [&](Index packed) { return ev[2 * (packed >> 1) + 1 - (packed & 1u)]; };
  for (Index packed : fe)
    if ((packed >> 1) >= ne) return false;
  const std::int64_t nfs = static_cast<std::int64_t>(nf);
#pragma omp parallel for schedule(static) reduction(&& : ok)
  for (std::int64_t f = 0; f < nfs; ++f) {
    const Index b = L.face_edge_offsets[f], m = L.face_edge_offsets[f + 1] - b;
    bool good = m >= 3;
    for (Index i = 0; i < m && good; ++i) {
      const Index p = fe[b + i];
      good = head(p) == tail(fe[b + (i + 1) % m]);
      for (Index j = 0; j < i && good; ++j) good = tail(fe[b + j]) != tail(p) && (fe[b + j] >> 1) != (p >> 1);
    }
    ok = ok && good;
  }
  if (!ok) return false;
  std::vector<Index> faces_at, faces;  // built: the faces of every edge, in face order
  invert(ne, nf, [&](std::size_t f, auto add) {
    for (Index k = L.face_edge_offsets[f]; k < L.face_edge_offsets[f + 1]; ++k) add(fe[k] >> 1);
  }, faces_at, faces);
  auto sameSet = [](std::span<const Index> built, std::span<const Index> listed) {
    if (built.size() != listed.size()) return false;
    for (Index x : built)  // built lists hold distinct items; short lists
      if (std::find(listed.begin(), listed.end(), x) == listed.end()) return false;
    return true;
  };
  auto list = [](const std::vector<Index>& offsets, const std::vector<Index>& items, std::size_t k) {
    return std::span<const Index>(items).subspan(offsets[k], offsets[k + 1] - offsets[k]);
  };
  const std::int64_t nes = static_cast<std::int64_t>(ne);
#pragma omp parallel for schedule(static) reduction(&& : ok)
  for (std::int64_t e = 0; e < nes; ++e) {
    const auto built = list(faces_at, faces, static_cast<std::size_t>(e));
    ok = ok && (L.dim == 3 || built.size() <= 2) && sameSet(built, list(L.edge_face_offsets, L.edge_faces, e));
  }
  if (!ok || L.dim == 2) return ok;
  // Volumes: at least 4 distinct live faces, each bounding at most two volumes, closed and oriented.
  const auto& vf = L.volume_faces;
  for (Index packed : vf)
    if ((packed >> 1) >= nf) return false;
  std::vector<Index> vols_at, vols;
  invert(nf, nc, [&](std::size_t k, auto add) {
    for (Index i = L.volume_face_offsets[k]; i < L.volume_face_offsets[k + 1]; ++i) add(vf[i] >> 1);
  }, vols_at, vols);
  const std::int64_t ncs = static_cast<std::int64_t>(nc);
#pragma omp parallel for schedule(static) reduction(&& : ok)
  for (std::int64_t f = 0; f < nfs; ++f) {
    const auto built = list(vols_at, vols, static_cast<std::size_t>(f));
    ok = ok && built.size() <= 2 && (built.size() < 2 || built[0] != built[1]) &&
         sameSet(built, list(L.face_volume_offsets, L.face_volumes, f));
  }
  if (!ok) return false;
#pragma omp parallel reduction(&& : ok)
  {
    std::vector<OrientedFace> surface;
    std::vector<OrientedEdge> loop;
    detail::ClosedSurfaceScratch edge_uses;
    auto loopOf = [&](FaceId f) -> const std::vector<OrientedEdge>& {
      loop.clear();
      for (Index packed : list(L.face_edge_offsets, fe, f.index()))
        loop.emplace_back(EdgeId(packed >> 1), (packed & 1u) != 0);
      return loop;
    };
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < ncs; ++k) {
      const auto items = list(L.volume_face_offsets, vf, static_cast<std::size_t>(k));
      surface.clear();
      for (Index packed : items) surface.emplace_back(FaceId(packed >> 1), (packed & 1u) != 0);
      ok = ok && items.size() >= 4 && detail::closedOrientedSurface(std::span<const OrientedFace>(surface), loopOf,
                                                                     nullptr, &edge_uses);
    }
  }
  return ok;
}

}  // namespace

CellComplex CellComplex::fromLayout(const ComplexLayout& layout) {
  CellComplex c(layout.dim);
  if (layout.edge_vertices.size() % 2 != 0)
    throw TopologyError("layout: the edge list holds an odd number of vertices");
  const std::size_t nv = layout.num_vertices, ne = layout.edge_vertices.size() / 2;
  const std::size_t nf = layout.face_edge_offsets.empty() ? 0 : layout.face_edge_offsets.size() - 1;
  const std::size_t nc = layout.volume_face_offsets.empty() ? 0 : layout.volume_face_offsets.size() - 1;
  if (layout.dim == 2 && nc != 0) throw TopologyError("layout: a 2D complex has no volumes");
  checkLists("face_edges", layout.face_edge_offsets, layout.face_edges.size(), nf);
  checkLists("volume_faces", layout.volume_face_offsets, layout.volume_faces.size(), nc);
  checkLists("vertex_edges", layout.vertex_edge_offsets, layout.vertex_edges.size(), nv);
  checkLists("edge_faces", layout.edge_face_offsets, layout.edge_faces.size(), ne);
  if (layout.dim == 3) checkLists("face_volumes", layout.face_volume_offsets, layout.face_volumes.size(), nf);
  if (bulkLayoutValid(layout, nv, ne, nf, nc)) {
    // Every list as listed: the pools are the layout's lists, unpacked.
    auto pool = [](const std::vector<Index>& offsets, std::size_t count, auto item, auto& out) {
      using Item = std::decay_t<decltype(item(Index{0}))>;
      UninitializedVector<Item> items(offsets[count]);  // every item written below
      std::vector<std::uint32_t> at(offsets.begin(), offsets.end() - 1), size(count);
      const std::int64_t n = static_cast<std::int64_t>(count);
#pragma omp parallel for schedule(static)
      for (std::int64_t k = 0; k < n; ++k) {
        size[k] = offsets[k + 1] - offsets[k];
        for (Index i = offsets[k]; i < offsets[k + 1]; ++i) items[i] = item(i);
      }
      out = RaggedArray<Item>::fromPool(std::move(items), at, size);
    };
    auto oriented = [](Index packed, auto handle) {
      return Oriented<decltype(handle)>(decltype(handle)(packed >> 1), (packed & 1u) != 0);
    };
    c.edge_vertices_.resize(ne);
    for (std::size_t e = 0; e < ne; ++e)
      c.edge_vertices_[e] = {VertexId(layout.edge_vertices[2 * e]), VertexId(layout.edge_vertices[2 * e + 1])};
    pool(layout.vertex_edge_offsets, nv, [&](Index i) { return EdgeId(layout.vertex_edges[i]); }, c.vertex_edges_);
    pool(layout.edge_face_offsets, ne, [&](Index i) { return FaceId(layout.edge_faces[i]); }, c.edge_faces_);
    pool(layout.face_edge_offsets, nf, [&](Index i) { return oriented(layout.face_edges[i], EdgeId()); },
         c.face_edges_);
    pool(layout.face_edge_offsets, nf, [&](Index i) {
      const Index p = layout.face_edges[i];
      return VertexId(layout.edge_vertices[2 * (p >> 1) + (p & 1u)]);  // the oriented edge's tail
    }, c.face_vertices_);
    if (layout.dim == 3) {
      pool(layout.face_volume_offsets, nf, [&](Index i) { return VolumeId(layout.face_volumes[i]); },
           c.face_volumes_);
      pool(layout.volume_face_offsets, nc, [&](Index i) { return oriented(layout.volume_faces[i], FaceId()); },
           c.volume_faces_);
    } else {
      const std::vector<Index> empty(nf + 1, 0);
      pool(empty, nf, [](Index) { return VolumeId(); }, c.face_volumes_);
    }
    const std::array<std::size_t, 4> counts{nv, ne, nf, nc};
    for (int d = 0; d <= 3; ++d) c.alive_[d].assign(counts[d], 1);
    c.live_count_ = counts;
    ++c.version_;
    return c;
  }
  auto list = [](const std::vector<Index>& offsets, const std::vector<Index>& items, std::size_t k) {
    return std::span<const Index>(items).subspan(offsets[k], offsets[k + 1] - offsets[k]);
  };
  // A defect: the checked construction element by element, in numbering order,
  // throws the first one with its location.
  for (std::size_t v = 0; v < nv; ++v) c.addVertex();
  for (std::size_t e = 0; e < ne; ++e) {
    const Index from = layout.edge_vertices[2 * e], to = layout.edge_vertices[2 * e + 1];
    try {
      c.addEdge(VertexId(from), VertexId(to));
    } catch (const TopologyError& error) {
      throw TopologyError(id("edge", static_cast<Index>(e)) + ": " + error.what(), {1, static_cast<Index>(e)});
    }
  }
  // (Scratch lists reused across elements: a snapshot of 1e6 cells has millions.)
  std::vector<OrientedEdge> loop;
  for (std::size_t f = 0; f < nf; ++f) {
    unpack<EdgeId>(list(layout.face_edge_offsets, layout.face_edges, f), loop);
    try {
      c.addFace(loop);
    } catch (const TopologyError& error) {
      throw TopologyError(id("face", static_cast<Index>(f)) + ": " + error.what(), {2, static_cast<Index>(f)});
    }
  }
  std::vector<OrientedFace> faces;
  for (std::size_t k = 0; k < nc; ++k) {
    unpack<FaceId>(list(layout.volume_face_offsets, layout.volume_faces, k), faces);
    try {
      c.addVolume(faces);
    } catch (const TopologyError& error) {
      throw TopologyError(id("volume", static_cast<Index>(k)) + ": " + error.what(), {3, static_cast<Index>(k)});
    }
  }
  // Regions: the same elements the borders gave, in the listed order.
  std::vector<Index> built, wanted;
  auto reorder = [&](int degree, auto& ragged, std::size_t count, const std::vector<Index>& offsets,
                     const std::vector<Index>& items, const char* what) {
    using Item = typename std::decay_t<decltype(ragged[0][0])>;
    std::vector<Item> ordered;
    for (std::size_t i = 0; i < count; ++i) {
      const auto stored = list(offsets, items, i);
      built.clear();
      for (Item x : ragged[i]) built.push_back(x.index());
      wanted.assign(stored.begin(), stored.end());
      std::sort(built.begin(), built.end());
      std::sort(wanted.begin(), wanted.end());
      if (built != wanted)
        throw TopologyError(id(degreeName(degree), static_cast<Index>(i)) + ": its " + what +
                                " list does not hold the elements its borders give",
                            {degree, static_cast<Index>(i)});
      ordered.clear();
      for (Index x : stored) ordered.emplace_back(x);
      ragged.assign(i, std::span<const Item>(ordered));
    }
  };
  reorder(0, c.vertex_edges_, nv, layout.vertex_edge_offsets, layout.vertex_edges, "edge");
  reorder(1, c.edge_faces_, ne, layout.edge_face_offsets, layout.edge_faces, "face");
  if (layout.dim == 3) reorder(2, c.face_volumes_, nf, layout.face_volume_offsets, layout.face_volumes, "volume");
  return c;
}


}  // namespace tessella
