// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/cell_complex.hpp"

#include <algorithm>
#include <exception>
#include <limits>
#include <numeric>
#include <span>
#include <type_traits>
#include <string>
#include <utility>

#include "closed_surface.hpp"
#include "tessella/tissue/huge_pages.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella {

namespace {

std::string id(const char* kind, Index i) { return std::string(kind) + " " + std::to_string(i); }

}  // namespace

CellComplex::CellComplex(int dim) : dim_(dim) {
  if (dim != 2 && dim != 3)
    throw InputError("a cell complex has dimension 2 or 3, not " + std::to_string(dim));
}

Index CellComplex::newSlot(int degree) {
  alive_[degree].push_back(1);
  ++live_count_[degree];
  ++version_;
  return static_cast<Index>(alive_[degree].size() - 1);
}

EdgeId CellComplex::findEdge(VertexId a, VertexId b) const {
  for (EdgeId e : vertex_edges_[a.index()]) {
    const auto& ev = edge_vertices_[e.index()];
    if ((ev[0] == a && ev[1] == b) || (ev[0] == b && ev[1] == a)) return e;
  }
  return EdgeId();
}

int CellComplex::loopPosition(FaceId f, EdgeId e) const {
  auto loop = face_edges_[f.index()];
  for (std::size_t i = 0; i < loop.size(); ++i)
    if (loop[i].handle() == e) return static_cast<int>(i);
  return -1;
}

int CellComplex::loopPosition(FaceId f, VertexId v) const {
  auto loop = face_vertices_[f.index()];
  for (std::size_t i = 0; i < loop.size(); ++i)
    if (loop[i] == v) return static_cast<int>(i);
  return -1;
}

int CellComplex::faceSign(VolumeId c, FaceId f) const {
  for (OrientedFace of : volume_faces_[c.index()])
    if (of.handle() == f) return of.sign();
  return 0;
}

VertexId CellComplex::addVertex() {
  const Index v = newSlot(0);
  vertex_edges_.pushList({});
  return VertexId(v);
}

EdgeId CellComplex::addEdge(VertexId from, VertexId to) {
  if (!alive(from) || !alive(to))
    throw TopologyError("edge from " + id("vertex", from.index()) + " to " + id("vertex", to.index()) +
                        ": vertex is not alive", {0, alive(from) ? to.index() : from.index()});
  if (from == to)
    throw TopologyError("edge from " + id("vertex", from.index()) + " to itself", {0, from.index()});
  if (EdgeId e = findEdge(from, to))
    throw TopologyError("an edge between vertices " + std::to_string(from.index()) + " and " +
                        std::to_string(to.index()) + " already exists (" + id("edge", e.index()) + ")",
                        {1, e.index()});
  const Index e = newSlot(1);
  edge_vertices_.push_back({from, to});
  edge_faces_.pushList({});
  vertex_edges_.pushBack(from.index(), EdgeId(e));
  vertex_edges_.pushBack(to.index(), EdgeId(e));
  return EdgeId(e);
}

void CellComplex::checkLoop(std::span<const OrientedEdge> loop) const {
  if (loop.size() < 3)
    throw TopologyError("a face loop needs at least 3 edges, got " + std::to_string(loop.size()));
  std::vector<Index> seen_vertices, seen_edges;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const EdgeId e = loop[i].handle();
    if (!alive(e)) throw TopologyError("face loop uses dead or invalid edge", {1, e.index()});
    const OrientedEdge next = loop[(i + 1) % loop.size()];
    if (head(loop[i]) != tail(next))
      throw TopologyError("face loop is not closed: " + id("edge", e.index()) + " ends at " +
                              id("vertex", head(loop[i]).index()) + " but " +
                              id("edge", next.handle().index()) + " starts at " +
                              id("vertex", tail(next).index()),
                          {1, e.index()});
    seen_vertices.push_back(tail(loop[i]).index());
    seen_edges.push_back(e.index());
  }
  std::sort(seen_vertices.begin(), seen_vertices.end());
  if (auto it = std::adjacent_find(seen_vertices.begin(), seen_vertices.end()); it != seen_vertices.end())
    throw TopologyError("face loop passes twice through " + id("vertex", *it), {0, *it});
  std::sort(seen_edges.begin(), seen_edges.end());
  if (auto it = std::adjacent_find(seen_edges.begin(), seen_edges.end()); it != seen_edges.end())
    throw TopologyError("face loop uses " + id("edge", *it) + " twice", {1, *it});
}

FaceId CellComplex::addFace(std::span<const OrientedEdge> loop) {
  checkLoop(loop);
  if (dim_ == 2) {
    for (OrientedEdge oe : loop) {
      const auto faces = edge_faces_[oe.handle().index()];
      if (faces.size() >= 2)
        throw TopologyError(id("edge", oe.handle().index()) + " already bounds two faces (" +
                                std::to_string(faces[0].index()) + ", " +
                                std::to_string(faces[1].index()) + ")",
                            {1, oe.handle().index()});
    }
  }
  const Index f = newSlot(2);
  face_edges_.pushList(loop);
  std::vector<VertexId> verts(loop.size());
  for (std::size_t i = 0; i < loop.size(); ++i) verts[i] = tail(loop[i]);
  face_vertices_.pushList(std::span<const VertexId>(verts));
  face_volumes_.pushList({});
  for (OrientedEdge oe : loop) edge_faces_.pushBack(oe.handle().index(), FaceId(f));
  return FaceId(f);
}

VolumeId CellComplex::addVolume(std::span<const OrientedFace> faces) {
  if (dim_ != 3) throw TopologyError("volumes exist only in a 3D complex");
  if (faces.size() < 4)
    throw TopologyError("a volume needs at least 4 faces, got " + std::to_string(faces.size()));
  std::vector<Index> seen;
  for (OrientedFace of : faces) {
    const FaceId f = of.handle();
    if (!alive(f)) throw TopologyError("volume uses dead or invalid face", {2, f.index()});
    if (face_volumes_[f.index()].size() >= 2)
      throw TopologyError(id("face", f.index()) + " already bounds two volumes", {2, f.index()});
    seen.push_back(f.index());
  }
  std::sort(seen.begin(), seen.end());
  if (auto it = std::adjacent_find(seen.begin(), seen.end()); it != seen.end())
    throw TopologyError("volume uses " + id("face", *it) + " twice", {2, *it});
  Index bad = kInvalidIndex;
  if (!detail::closedOrientedSurface(faces, [&](FaceId f) { return faceEdges(f); }, &bad))
    throw TopologyError("volume surface is not closed and consistently oriented at " + id("edge", bad),
                        {1, bad});
  const Index c = newSlot(3);
  volume_faces_.pushList(faces);
  for (OrientedFace of : faces) face_volumes_.pushBack(of.handle().index(), VolumeId(c));
  return VolumeId(c);
}

CellComplex CellComplex::fromLoops(int dim, std::size_t num_vertices, std::span<const Index> loop_offsets,
                                   std::span<const Index> loop_vertices, std::span<const Index> face_ids) {
  CellComplex c(dim);
  const std::size_t nf = loop_offsets.empty() ? 0 : loop_offsets.size() - 1;
  const std::size_t total = nf ? loop_offsets[nf] : 0;
  if (nf && (loop_offsets[0] != 0 || total != loop_vertices.size()))
    throw TopologyError("fromLoops: offsets do not cover the vertex list");
  if (total > std::numeric_limits<std::uint32_t>::max() / 2)
    throw TopologyError("fromLoops: " + std::to_string(total) + " loop vertices are more than one complex holds");
  if (!face_ids.empty()) {
    if (face_ids.size() != nf)
      throw TopologyError("fromLoops: the face ids list " + std::to_string(face_ids.size()) + " faces, not " +
                          std::to_string(nf));
    std::vector<std::uint8_t> listed(nf, 0);
    for (Index f : face_ids) {
      if (f >= nf || listed[f])
        throw TopologyError("fromLoops: the face ids are not a permutation (face " + std::to_string(f) + ")");
      listed[f] = 1;
    }
  }
  // Loop q is face faceOf(q); every pass below reads the loops in list order.
  auto faceOf = [&](std::size_t q) -> Index { return face_ids.empty() ? static_cast<Index>(q) : face_ids[q]; };
  // Check every loop first, so that an error leaves nothing half built.
  // Each edge is found in the half star of its lower vertex: the edges whose
  // lower end it is, with their higher ends (the key a loop side looks up).
  // Counted here per loop side, at the side's lower end: an upper bound.
  UninitializedVector<std::uint32_t> half_start = detail::freshArray<std::uint32_t>(num_vertices + 1, 0);
  UninitializedVector<Index> last_loop = detail::freshArray<Index>(num_vertices, kInvalidIndex);  // repeats show here
  for (std::size_t q = 0; q < nf; ++q) {
    const auto loop = loop_vertices.subspan(loop_offsets[q], loop_offsets[q + 1] - loop_offsets[q]);
    const Index fi = faceOf(q);
    if (loop.size() < 3)
      throw TopologyError(id("face", fi) + " has " + std::to_string(loop.size()) + " vertices (at least 3 needed)",
                          {2, fi});
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index v = loop[i];
      if (v >= num_vertices)
        throw TopologyError(id("face", fi) + " uses vertex " + std::to_string(v) + " but there are only " +
                                std::to_string(num_vertices) + " vertices",
                            {2, fi});
      if (last_loop[v] == q) throw TopologyError(id("face", fi) + " passes twice through " + id("vertex", v), {2, fi});
      last_loop[v] = static_cast<Index>(q);
      ++half_start[std::min(v, loop[i + 1 < loop.size() ? i + 1 : 0])];  // <= v: in range even if the next is not
    }
  }
  std::exclusive_scan(half_start.begin(), half_start.end(), half_start.begin(), std::uint32_t{0});
  // The edges in order of first use. Half star items: the higher end and the
  // edge, whose top bit (free: total < 2^31) says that the edge starts at the
  // lower end, so that a side's orientation needs no look-up in edge_vertices_.
  struct HalfStarItem {
    Index other;
    std::uint32_t edge_and_from_lower;
  };
  constexpr std::uint32_t kFromLower = std::uint32_t{1} << 31;
  UninitializedVector<HalfStarItem> half = detail::freshArray<HalfStarItem>(total);
  UninitializedVector<std::uint32_t> half_count = std::move(last_loop);  // its memory again, now a count per vertex
  std::fill(half_count.begin(), half_count.end(), 0);
  UninitializedVector<std::uint32_t> degree = detail::freshArray<std::uint32_t>(num_vertices + 1, 0);  // edges per vertex
  c.edge_vertices_ = detail::freshArray<std::array<VertexId, 2>>(total);  // an upper bound, cut to size below
  UninitializedVector<std::uint32_t> edge_face_count = detail::freshArray<std::uint32_t>(total);
  UninitializedVector<OrientedEdge> face_edges = detail::freshArray<OrientedEdge>(total);  // in list order
  // Edge -> faces. 2D: at most two faces per edge, kept in a pair of slots
  // per edge (the second use of an edge comes soon after its first when
  // nearby faces are listed together). 3D: read back afterwards from the
  // faces' edge lists, in list order.
  UninitializedVector<FaceId> edge_face_slots;
  if (dim == 2) edge_face_slots = detail::freshArray<FaceId>(2 * total);
  std::uint32_t ne = 0;
  for (std::size_t q = 0; q < nf; ++q) {
    const std::size_t b = loop_offsets[q], m = loop_offsets[q + 1] - b;
    const Index f = faceOf(q);
    for (std::size_t i = 0; i < m; ++i) {
      const Index a = loop_vertices[b + i], h = loop_vertices[i + 1 < m ? b + i + 1 : b];
      const Index lo = std::min(a, h), hi = std::max(a, h);
      HalfStarItem* const items = half.data() + half_start[lo];
      const std::uint32_t n = half_count[lo];
      std::uint32_t item = kInvalidIndex;
      for (std::uint32_t k = 0; k < n; ++k)
        if (items[k].other == hi) {
          item = items[k].edge_and_from_lower;
          break;
        }
      if (item == kInvalidIndex) {  // a new edge, from a to h
        item = ne | (a == lo ? kFromLower : 0);
        c.edge_vertices_[ne] = {VertexId(a), VertexId(h)};
        edge_face_count[ne] = 0;
        if (dim == 2) edge_face_slots[2 * ne] = edge_face_slots[2 * ne + 1] = FaceId();
        items[n] = {hi, item};
        half_count[lo] = n + 1;
        ++degree[a];
        ++degree[h];
        ++ne;
      }
      const std::uint32_t e = item & ~kFromLower;
      if (dim == 2 && edge_face_count[e] == 2)
        throw TopologyError(id("face", f) + ": " + id("edge", e) + " (vertices " + std::to_string(a) + ", " +
                                std::to_string(h) + ") already bounds two faces",
                            {2, f});
      if (dim == 2) edge_face_slots[2 * e + edge_face_count[e]] = FaceId(f);
      ++edge_face_count[e];
      // Reversed when the edge does not start at a, i.e. it starts at the lower end and a is the higher, or
      // the other way round.
      face_edges[b + i] = OrientedEdge(EdgeId(e), ((item & kFromLower) != 0) != (a == lo));
    }
  }
  half = {};
  c.edge_vertices_.resize(ne);
  edge_face_count.resize(ne);
  if (dim == 2) edge_face_slots.resize(2 * std::size_t{ne});
  c.live_count_ = {num_vertices, ne, nf, 0};
  // The rest is two independent parts, the vertex stars and the face and
  // edge -> face lists, which two threads make side by side (one region: a
  // team per loop costs more than these loops on a busy machine).
  std::exception_ptr failed[2];
#pragma omp parallel sections num_threads(2) if (total >= kParallelCopyMin)
  {
#pragma omp section
    try {
      // Vertex stars: every edge at both ends, in edge id order (as addEdge appends them).
      UninitializedVector<std::uint32_t>& star_start = degree;  // the degrees summed in place
      std::exclusive_scan(degree.begin(), degree.end(), star_start.begin(), std::uint32_t{0});
      UninitializedVector<EdgeId> star = detail::freshArray<EdgeId>(2 * std::size_t{ne});
      UninitializedVector<std::uint32_t>& star_end = half_count;  // a cursor per vertex: where its star is filled to
      std::copy_n(star_start.begin(), num_vertices, star_end.begin());
      for (std::uint32_t e = 0; e < ne; ++e)
        for (VertexId v : c.edge_vertices_[e]) star[star_end[v.index()]++] = EdgeId(e);
      for (std::size_t v = 0; v < num_vertices; ++v) star_end[v] -= star_start[v];  // now each star's size
      // edge_vertices_ to its size (it had room for one edge per loop side): bytes() counts capacity.
      UninitializedVector<std::array<VertexId, 2>> edge_vertices = detail::freshArray<std::array<VertexId, 2>>(ne);
      std::copy_n(c.edge_vertices_.begin(), ne, edge_vertices.begin());
      c.edge_vertices_.swap(edge_vertices);
      c.alive_[0].assign(num_vertices, 1);
      c.vertex_edges_ = RaggedArray<EdgeId>::fromPool(std::move(star), std::span(star_start).first(num_vertices),
                                                      std::span(star_end).first(num_vertices));
    } catch (...) {
      failed[0] = std::current_exception();
    }
#pragma omp section
    try {
      c.alive_[1].assign(ne, 1);
      c.alive_[2].assign(nf, 1);
      // Face lists stay where the loops are (list order); face f's slot points there.
      std::vector<std::uint32_t> at(nf), size(nf);
      for (std::size_t q = 0; q < nf; ++q) {
        const Index f = faceOf(q);
        at[f] = loop_offsets[q];
        size[f] = loop_offsets[q + 1] - loop_offsets[q];
      }
      UninitializedVector<VertexId> face_vertices = detail::freshArray<VertexId>(total);
      std::transform(loop_vertices.begin(), loop_vertices.end(), face_vertices.begin(),
                     [](Index v) { return VertexId(v); });
      c.face_edges_ = RaggedArray<OrientedEdge>::fromPool(std::move(face_edges), at, size);
      c.face_vertices_ = RaggedArray<VertexId>::fromPool(std::move(face_vertices), at, size);
      std::fill(at.begin(), at.end(), 0);
      std::fill(size.begin(), size.end(), 0);
      c.face_volumes_ = RaggedArray<VolumeId>::fromPool({}, at, size);
      // Edge -> faces, each list in face id order (as addFace would append them).
      if (dim == 2) {
        UninitializedVector<std::uint32_t> ef_at = detail::freshArray<std::uint32_t>(ne);
        for (std::uint32_t e = 0; e < ne; ++e) {
          ef_at[e] = 2 * e;
          if (edge_face_count[e] == 2 && edge_face_slots[2 * e + 1] < edge_face_slots[2 * e])
            std::swap(edge_face_slots[2 * e], edge_face_slots[2 * e + 1]);
        }
        c.edge_faces_ = RaggedArray<FaceId>::fromPool(std::move(edge_face_slots), ef_at, edge_face_count);
      } else {
        std::vector<std::uint32_t> ef_start(ne + 1, 0);
        for (std::size_t e = 0; e < ne; ++e) ef_start[e + 1] = ef_start[e] + edge_face_count[e];
        UninitializedVector<FaceId> ef(ef_start[ne]);
        std::fill(edge_face_count.begin(), edge_face_count.end(), 0);
        for (std::size_t q = 0; q < nf; ++q) {
          const FaceId f(faceOf(q));
          for (OrientedEdge oe : c.face_edges_[f.index()]) {  // (the loop's slots, in list order)
            const Index e = oe.handle().index();
            ef[ef_start[e] + edge_face_count[e]++] = f;
          }
        }
        if (!face_ids.empty())  // filled in list order: back to face id order
          for (std::size_t e = 0; e < ne; ++e)
            std::sort(ef.begin() + static_cast<std::ptrdiff_t>(ef_start[e]),
                      ef.begin() + static_cast<std::ptrdiff_t>(ef_start[e + 1]));
        c.edge_faces_ =
            RaggedArray<FaceId>::fromPool(std::move(ef), std::span(ef_start).first(ne), edge_face_count);
      }
    } catch (...) {
      failed[1] = std::current_exception();
    }
  }
  for (const std::exception_ptr& f : failed)
    if (f) std::rethrow_exception(f);
  ++c.version_;
  return c;
}

void CellComplex::addVolumes(std::span<const Index> offsets, std::span<const OrientedFace> faces,
                             std::span<const std::uint8_t> closed_by_construction) {
  if (dim_ != 3) throw TopologyError("volumes exist only in a 3D complex");
  const std::size_t nv = offsets.empty() ? 0 : offsets.size() - 1;
  if (nv && (offsets[0] != 0 || offsets[nv] != faces.size()))
    throw TopologyError("addVolumes: offsets do not cover the face list");
  if (!closed_by_construction.empty() && closed_by_construction.size() != nv)
    throw TopologyError("addVolumes: " + std::to_string(closed_by_construction.size()) +
                        " closed-by-construction flags for " + std::to_string(nv) + " volumes");
  // A volume the caller built closed skips the closed-surface check (the
  // other checks still run); debug and paranoid builds check every volume.
#if !defined(NDEBUG) || defined(TESSELLA_PARANOID)
  closed_by_construction = {};
#endif
  // Per-volume checks are independent: run them in parallel, report the
  // first. They visit the volumes by their highest face id: when faces are
  // numbered along space (generators), volumes listed in another order
  // (cell k = seed k) are then checked without missing the cache at every
  // face. (Highest rather than lowest: when each wall is stored with the lower
  // of its two cells, as the Voronoi generators do, a cell's highest face ids
  // are the walls it stores itself, so volumes are visited in the order their
  // walls were stored; ~5-10 % faster on 1e5 Voronoi cells.)
  std::vector<std::uint8_t> bad(nv, 0);
  const std::int64_t nvs = static_cast<std::int64_t>(nv);
  std::vector<std::pair<Index, Index>> visit(nv);  // (highest face id, volume)
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < nvs; ++k) {
    Index highest = 0;
    for (Index i = offsets[k]; i < offsets[k + 1]; ++i) highest = std::max(highest, faces[i].handle().index());
    visit[k] = {highest, static_cast<Index>(k)};
  }
  std::sort(visit.begin(), visit.end());
#pragma omp parallel
  {
    std::vector<Index> seen;  // per thread, reused
    detail::ClosedSurfaceScratch edge_uses;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t m = 0; m < nvs; ++m) {
      const Index k = visit[m].second;
      const auto list = faces.subspan(offsets[k], offsets[k + 1] - offsets[k]);
      if (list.size() < 4) { bad[k] = 1; continue; }
      seen.clear();
      for (OrientedFace of : list) {
        if (!alive(of.handle())) { bad[k] = 1; break; }
        seen.push_back(of.handle().index());
      }
      if (bad[k]) continue;
      std::sort(seen.begin(), seen.end());
      if (std::adjacent_find(seen.begin(), seen.end()) != seen.end() ||
          ((closed_by_construction.empty() || !closed_by_construction[k]) &&
           !detail::closedOrientedSurface(list, [&](FaceId f) { return faceEdges(f); }, nullptr, &edge_uses)))
        bad[k] = 1;
    }
  }
  std::vector<std::uint32_t> uses(face_volumes_.size(), 0);
  for (std::size_t f = 0; f < uses.size(); ++f) uses[f] = face_volumes_.listSize(f);
  // The volume's name is spelled out only when a check fails.
  auto volumeName = [&](std::size_t k) { return "volume " + std::to_string(volume_faces_.size() + k); };
  for (std::size_t k = 0; k < nv; ++k) {
    const auto list = faces.subspan(offsets[k], offsets[k + 1] - offsets[k]);
    const ElementId where{3, static_cast<Index>(volume_faces_.size() + k)};
    if (bad[k]) {
      const std::string vol = volumeName(k);
      if (list.size() < 4)
        throw TopologyError(vol + " needs at least 4 faces, got " + std::to_string(list.size()), where);
      std::vector<Index> seen;
      for (OrientedFace of : list) {
        if (!alive(of.handle()))
          throw TopologyError(vol + " uses dead or invalid " + id("face", of.handle().index()), where);
        seen.push_back(of.handle().index());
      }
      std::sort(seen.begin(), seen.end());
      if (auto it = std::adjacent_find(seen.begin(), seen.end()); it != seen.end())
        throw TopologyError(vol + " uses " + id("face", *it) + " twice", where);
      Index bad_edge = kInvalidIndex;
      detail::closedOrientedSurface(list, [&](FaceId f) { return faceEdges(f); }, &bad_edge);
      throw TopologyError(vol + ": surface is not closed and consistently oriented at " + id("edge", bad_edge),
                          where);
    }
    for (OrientedFace of : list)
      if (++uses[of.handle().index()] > 2)
        throw TopologyError(volumeName(k) + ": " + id("face", of.handle().index()) + " already bounds two volumes",
                            where);
  }
  // Rebuild face -> volumes in one pass (old lists first, then the new volumes in order).
  // (At most two volumes per face: the pool's offsets fit 32 bits.)
  const Index first = static_cast<Index>(volume_faces_.size());
  std::vector<std::uint32_t> start(uses.size() + 1, 0);
  for (std::size_t f = 0; f < uses.size(); ++f) start[f + 1] = start[f] + uses[f];
  UninitializedVector<VolumeId> fv(start.back());  // every item written below
  std::vector<std::uint32_t> fill(uses.size(), 0);
  for (std::size_t f = 0; f < uses.size(); ++f)
    for (VolumeId v : face_volumes_[f]) fv[start[f] + fill[f]++] = v;
  for (std::size_t k = 0; k < nv; ++k)
    for (Index i = offsets[k]; i < offsets[k + 1]; ++i) {
      const Index f = faces[i].handle().index();
      fv[start[f] + fill[f]++] = VolumeId(first + static_cast<Index>(k));
    }
  face_volumes_ =
      RaggedArray<VolumeId>::fromPool(std::move(fv), std::span(start).first(uses.size()), uses);
  volume_faces_.reserve(volume_faces_.size() + nv, faces.size());
  alive_[3].reserve(alive_[3].size() + nv);
  for (std::size_t k = 0; k < nv; ++k) {
    (void)newSlot(3);
    volume_faces_.pushList(faces.subspan(offsets[k], offsets[k + 1] - offsets[k]));
  }
}

void CellComplex::remove(int degree, Index i) {
  if (degree < 0 || degree > dim_ || !alive(degree, i))
    throw TopologyError("cannot remove " + id(degreeName(degree), i) + ": not alive", {degree, i});
  switch (degree) {
    case 0:
      if (!vertex_edges_[i].empty())
        throw TopologyError("cannot remove " + id("vertex", i) + ": edges still use it", {0, i});
      break;
    case 1: {
      if (!edge_faces_[i].empty())
        throw TopologyError("cannot remove " + id("edge", i) + ": faces still use it", {1, i});
      for (VertexId v : edge_vertices_[i]) vertex_edges_.eraseValue(v.index(), EdgeId(i));
      break;
    }
    case 2: {
      if (!face_volumes_[i].empty())
        throw TopologyError("cannot remove " + id("face", i) + ": volumes still use it", {2, i});
      for (OrientedEdge oe : face_edges_[i]) edge_faces_.eraseValue(oe.handle().index(), FaceId(i));
      face_edges_.clearList(i);
      face_vertices_.clearList(i);
      break;
    }
    case 3: {
      for (OrientedFace of : volume_faces_[i])
        face_volumes_.eraseValue(of.handle().index(), VolumeId(i));
      volume_faces_.clearList(i);
      break;
    }
  }
  alive_[degree][i] = 0;
  --live_count_[degree];
  ++version_;
}

std::pair<VertexId, EdgeId> CellComplex::splitEdge(EdgeId e) {
  if (!alive(e)) throw TopologyError("cannot split dead " + id("edge", e.index()), {1, e.index()});
  const VertexId b = edgeTo(e);
  const VertexId v = addVertex();
  const EdgeId e2(newSlot(1));
  edge_vertices_.push_back({v, b});
  edge_vertices_[e.index()][1] = v;
  vertex_edges_.replaceValue(b.index(), e, e2);
  vertex_edges_.pushBack(v.index(), e);
  vertex_edges_.pushBack(v.index(), e2);
  const std::vector<FaceId> faces(edge_faces_[e.index()].begin(), edge_faces_[e.index()].end());
  edge_faces_.pushList(std::span<const FaceId>(faces));
  for (FaceId f : faces) {
    const int p = loopPosition(f, e);
    const bool reversed = face_edges_[f.index()][p].reversed();
    // Forward: ... a->v (e), v->b (e2) ...   Reversed: ... b->v (e2~), v->a (e~) ...
    face_edges_.insert(f.index(), reversed ? p : p + 1, OrientedEdge(e2, reversed));
    face_vertices_.insert(f.index(), p + 1, v);
  }
  return {v, e2};
}

std::pair<EdgeId, FaceId> CellComplex::splitFace(FaceId f, VertexId a, VertexId b) {
  if (!alive(f)) throw TopologyError("cannot split dead " + id("face", f.index()), {2, f.index()});
  const int ia = loopPosition(f, a), ib = loopPosition(f, b);
  const int n = static_cast<int>(face_vertices_[f.index()].size());
  if (ia < 0 || ib < 0)
    throw TopologyError("cannot split " + id("face", f.index()) + ": " +
                            id("vertex", (ia < 0 ? a : b).index()) + " is not on its loop",
                        {2, f.index()});
  if (ia == ib || (ia + 1) % n == ib || (ib + 1) % n == ia)
    throw TopologyError("cannot split " + id("face", f.index()) + " between vertices " +
                            std::to_string(a.index()) + " and " + std::to_string(b.index()) +
                            ": they are equal or adjacent on its loop",
                        {2, f.index()});
  if (EdgeId existing = findEdge(a, b))
    throw TopologyError("cannot split " + id("face", f.index()) + ": vertices " +
                            std::to_string(a.index()) + " and " + std::to_string(b.index()) +
                            " are already joined by " + id("edge", existing.index()),
                        {1, existing.index()});
  const std::vector<OrientedEdge> loop(face_edges_[f.index()].begin(), face_edges_[f.index()].end());
  const EdgeId e = addEdge(a, b);
  std::vector<OrientedEdge> keep, move;
  for (int i = ia; i != ib; i = (i + 1) % n) keep.push_back(loop[i]);
  keep.push_back(OrientedEdge(e, true));  // b -> a
  for (int i = ib; i != ia; i = (i + 1) % n) move.push_back(loop[i]);
  move.push_back(OrientedEdge(e, false));  // a -> b
  auto tails = [&](const std::vector<OrientedEdge>& l) {
    std::vector<VertexId> v(l.size());
    for (std::size_t i = 0; i < l.size(); ++i) v[i] = tail(l[i]);
    return v;
  };
  const FaceId f2(newSlot(2));
  face_edges_.assign(f.index(), std::span<const OrientedEdge>(keep));
  face_vertices_.assign(f.index(), std::span<const VertexId>(tails(keep)));
  face_edges_.pushList(std::span<const OrientedEdge>(move));
  face_vertices_.pushList(std::span<const VertexId>(tails(move)));
  for (std::size_t i = 0; i + 1 < move.size(); ++i)
    edge_faces_.replaceValue(move[i].handle().index(), f, f2);
  edge_faces_.pushBack(e.index(), f);
  edge_faces_.pushBack(e.index(), f2);
  const std::vector<VolumeId> vols(face_volumes_[f.index()].begin(), face_volumes_[f.index()].end());
  face_volumes_.pushList(std::span<const VolumeId>(vols));
  for (VolumeId c : vols) volume_faces_.pushBack(c.index(), OrientedFace(f2, faceSign(c, f) < 0));
  return {e, f2};
}

std::pair<FaceId, VolumeId> CellComplex::splitVolume(VolumeId c, std::span<const FaceId> moving,
                                                     std::span<const OrientedEdge> cut_loop,
                                                     int cut_sign) {
  if (!alive(c)) throw TopologyError("cannot split dead " + id("volume", c.index()), {3, c.index()});
  checkLoop(cut_loop);
  // Build both new face lists and check they are closed before touching anything.
  std::vector<OrientedFace> stay, go;
  for (OrientedFace of : volume_faces_[c.index()]) {
    const bool moves = std::find(moving.begin(), moving.end(), of.handle()) != moving.end();
    (moves ? go : stay).push_back(of);
  }
  if (go.size() != moving.size())
    throw TopologyError("splitVolume: a moving face does not bound " + id("volume", c.index()),
                        {3, c.index()});
  // The cut face's edges, seen as a temporary face for the closure test.
  constexpr Index kCutFace = 0x7FFFFFFE;  // not a real face: indices stay below 2^31
  auto loopOf = [&](FaceId f) -> std::span<const OrientedEdge> {
    return f.index() == kCutFace ? cut_loop : faceEdges(f);
  };
  stay.push_back(OrientedFace(FaceId(kCutFace), cut_sign < 0));
  go.push_back(OrientedFace(FaceId(kCutFace), cut_sign > 0));
  Index bad = kInvalidIndex;
  if (!detail::closedOrientedSurface(std::span<const OrientedFace>(stay), loopOf, &bad) ||
      !detail::closedOrientedSurface(std::span<const OrientedFace>(go), loopOf, &bad))
    throw TopologyError("splitting " + id("volume", c.index()) +
                            " would leave an open surface at " + id("edge", bad),
                        {3, c.index()});
  stay.pop_back();
  go.pop_back();
  const FaceId cut = addFace(cut_loop);
  const VolumeId c2(newSlot(3));
  stay.push_back(OrientedFace(cut, cut_sign < 0));
  go.push_back(OrientedFace(cut, cut_sign > 0));
  volume_faces_.assign(c.index(), std::span<const OrientedFace>(stay));
  volume_faces_.pushList(std::span<const OrientedFace>(go));
  for (FaceId f : moving) face_volumes_.replaceValue(f.index(), c, c2);
  face_volumes_.pushBack(cut.index(), c);
  face_volumes_.pushBack(cut.index(), c2);
  return {cut, c2};
}

ComplexLayout CellComplex::layout() const {
  ComplexLayout out;
  out.dim = dim_;
  std::array<std::vector<Index>, 4> rank;
  for (int d = 0; d <= dim_; ++d) {
    rank[d].assign(alive_[d].size(), kInvalidIndex);
    Index next = 0;
    for (std::size_t i = 0; i < alive_[d].size(); ++i)
      if (alive_[d][i]) rank[d][i] = next++;
  }
  out.num_vertices = live_count_[0];
  auto packed = [&](int degree, auto oriented) {
    return (rank[degree][oriented.handle().index()] << 1) | (oriented.reversed() ? 1u : 0u);
  };
  // Every live list of one degree, mapped item by item, as CSR.
  auto lists = [&](int degree, const auto& ragged, std::vector<Index>& offsets, std::vector<Index>& items,
                   auto item) {
    offsets.assign(1, 0);
    for (std::size_t i = 0; i < alive_[degree].size(); ++i) {
      if (!alive_[degree][i]) continue;
      for (const auto& x : ragged[i]) items.push_back(item(x));
      offsets.push_back(static_cast<Index>(items.size()));
    }
  };
  for (std::size_t e = 0; e < edge_vertices_.size(); ++e)
    if (alive_[1][e])
      for (VertexId v : edge_vertices_[e]) out.edge_vertices.push_back(rank[0][v.index()]);
  lists(2, face_edges_, out.face_edge_offsets, out.face_edges, [&](OrientedEdge oe) { return packed(1, oe); });
  lists(0, vertex_edges_, out.vertex_edge_offsets, out.vertex_edges, [&](EdgeId e) { return rank[1][e.index()]; });
  lists(1, edge_faces_, out.edge_face_offsets, out.edge_faces, [&](FaceId f) { return rank[2][f.index()]; });
  if (dim_ == 3) {
    lists(3, volume_faces_, out.volume_face_offsets, out.volume_faces,
          [&](OrientedFace of) { return packed(2, of); });
    lists(2, face_volumes_, out.face_volume_offsets, out.face_volumes,
          [&](VolumeId c) { return rank[3][c.index()]; });
  } else {
    out.volume_face_offsets.assign(1, 0);
    out.face_volume_offsets.assign(1, 0);
  }
  return out;
}

Renumbering CellComplex::compact() {
  Renumbering r;
  std::array<std::size_t, 4> counts{};
  for (int d = 0; d <= 3; ++d) {
    auto& map = r.old_to_new[d];
    map.assign(alive_[d].size(), kInvalidIndex);
    Index next = 0;
    for (std::size_t i = 0; i < alive_[d].size(); ++i)
      if (alive_[d][i]) map[i] = next++;
    counts[d] = next;
  }
  const auto& m = r.old_to_new;
  auto mapV = [&](VertexId v) { return VertexId(m[0][v.index()]); };
  auto mapE = [&](EdgeId e) { return EdgeId(m[1][e.index()]); };
  auto mapF = [&](FaceId f) { return FaceId(m[2][f.index()]); };
  auto mapC = [&](VolumeId c) { return VolumeId(m[3][c.index()]); };
  {
    UninitializedVector<std::array<VertexId, 2>> ev(counts[1]);
    for (std::size_t i = 0; i < edge_vertices_.size(); ++i)
      if (m[1][i] != kInvalidIndex) ev[m[1][i]] = {mapV(edge_vertices_[i][0]), mapV(edge_vertices_[i][1])};
    edge_vertices_ = std::move(ev);
  }
  vertex_edges_.compact(m[0], counts[0], mapE);
  edge_faces_.compact(m[1], counts[1], mapF);
  face_edges_.compact(m[2], counts[2],
                      [&](OrientedEdge oe) { return OrientedEdge(mapE(oe.handle()), oe.reversed()); });
  face_vertices_.compact(m[2], counts[2], mapV);
  face_volumes_.compact(m[2], counts[2], mapC);
  volume_faces_.compact(m[3], counts[3],
                        [&](OrientedFace of) { return OrientedFace(mapF(of.handle()), of.reversed()); });
  for (int d = 0; d <= 3; ++d) {
    alive_[d].assign(counts[d], 1);
    live_count_[d] = counts[d];
  }
  ++version_;
  return r;
}

std::size_t CellComplex::bytes() const {
  std::size_t b = edge_vertices_.capacity() * sizeof(edge_vertices_[0]);
  for (const auto& a : alive_) b += a.capacity();
  return b + face_edges_.bytes() + face_vertices_.bytes() + volume_faces_.bytes() +
         vertex_edges_.bytes() + edge_faces_.bytes() + face_volumes_.bytes();
}

}  // namespace tessella
