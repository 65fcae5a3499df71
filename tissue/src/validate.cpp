// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/validate.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella {

namespace {

struct Fail {
  ValidationReport report;
};

[[noreturn]] void fail(int degree, Index i, const std::string& what) {
  ValidationReport r;
  r.ok = false;
  r.element = {degree, i};
  r.message = std::string(degreeName(degree)) + " " + std::to_string(i) + ": " + what;
  throw Fail{r};
}

template <typename H, typename Span>
bool contains(const Span& s, H h) {
  return std::find(s.begin(), s.end(), h) != s.end();
}

struct UnionFind {
  std::vector<Index> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), Index(0)); }
  Index find(Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(Index a, Index b) { parent[find(a)] = find(b); }
};

// The vertex ids of f's loop, sorted, into `key` (reused: no allocation per face).
void sortedVertices(const CellComplex& k, FaceId f, std::vector<Index>& key) {
  key.clear();
  for (VertexId v : k.faceVertices(f)) key.push_back(v.index());
  std::sort(key.begin(), key.end());
}

// For each live face, the first face (in index order) with the same vertex
// set, or kInvalidIndex: faces sorted by a hash of their sorted vertex list,
// and only faces of equal hash compared in full (no hash map of keys).
std::vector<Index> duplicateFaces(const CellComplex& k, std::span<const FaceId> faces) {
  std::vector<Index> first(k.slots(2), kInvalidIndex);
  std::vector<std::pair<std::uint64_t, Index>> hashed;
  hashed.reserve(faces.size());
  std::vector<Index> key, other;
  for (FaceId f : faces) {
    sortedVertices(k, f, key);
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the sorted ids
    for (Index v : key) h = (h ^ v) * 1099511628211ull;
    hashed.emplace_back(h, f.index());
  }
  std::sort(hashed.begin(), hashed.end());
  for (std::size_t a = 0; a < hashed.size();) {
    std::size_t b = a + 1;
    while (b < hashed.size() && hashed[b].first == hashed[a].first) ++b;
    for (std::size_t j = a + 1; j < b; ++j) {  // ascending face index within a run of equal hashes
      sortedVertices(k, FaceId(hashed[j].second), key);
      for (std::size_t i = a; i < j; ++i) {
        sortedVertices(k, FaceId(hashed[i].second), other);
        if (other == key) {
          first[hashed[j].second] = hashed[i].second;
          break;
        }
      }
    }
    a = b;
  }
  return first;
}

void checkIncidence(const Tissue& t) {
  const CellComplex& k = t.topology();
  const int D = t.dim();
  std::vector<EdgeId> s;  // reused for each vertex's star
  for (VertexId v : t.vertices()) {
    const auto star = k.vertexEdges(v);
    if (star.empty()) fail(0, v.index(), "dangling (bounds no edge)");
    for (EdgeId e : star) {
      if (!k.alive(e)) fail(0, v.index(), "its star lists dead edge " + std::to_string(e.index()));
      const auto ev = k.edgeVertices(e);
      if (ev[0] != v && ev[1] != v) fail(0, v.index(), "its star lists edge " + std::to_string(e.index()) + " which does not end at it");
    }
    s.assign(star.begin(), star.end());
    std::sort(s.begin(), s.end());
    if (std::adjacent_find(s.begin(), s.end()) != s.end()) fail(0, v.index(), "an edge appears twice in its star");
    if (!t.position(v).allFinite()) fail(0, v.index(), "position is not finite");
  }
  for (EdgeId e : t.edges()) {
    const auto ev = k.edgeVertices(e);
    for (VertexId v : ev) {
      if (!k.alive(v)) fail(1, e.index(), "ends at dead vertex " + std::to_string(v.index()));
      if (!contains(k.vertexEdges(v), e)) fail(1, e.index(), "missing from the star of vertex " + std::to_string(v.index()));
    }
    if (ev[0] == ev[1]) fail(1, e.index(), "both ends are vertex " + std::to_string(ev[0].index()));
    if (k.findEdge(ev[0], ev[1]) != e)
      fail(1, e.index(), "duplicates edge " + std::to_string(k.findEdge(ev[0], ev[1]).index()));
    const auto faces = k.edgeFaces(e);
    if (faces.empty()) fail(1, e.index(), "dangling (bounds no face)");
    if (D == 2 && faces.size() > 2) fail(1, e.index(), "bounds " + std::to_string(faces.size()) + " cells (at most 2 in a 2D tissue)");
    for (FaceId f : faces) {
      if (!k.alive(f)) fail(1, e.index(), "regions list dead face " + std::to_string(f.index()));
      if (k.loopPosition(f, e) < 0) fail(1, e.index(), "regions list face " + std::to_string(f.index()) + " whose loop does not use it");
    }
  }
  const std::vector<FaceId> live_faces(t.faces().begin(), t.faces().end());
  const std::vector<Index> duplicate_of = duplicateFaces(k, live_faces);
  std::vector<Index> key;
  for (FaceId f : live_faces) {
    const auto loop = k.faceEdges(f);
    const auto verts = k.faceVertices(f);
    if (loop.size() < 3) fail(2, f.index(), "loop has " + std::to_string(loop.size()) + " edges");
    if (verts.size() != loop.size()) fail(2, f.index(), "vertex loop and edge loop differ in length");
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const EdgeId e = loop[i].handle();
      if (!k.alive(e)) fail(2, f.index(), "loop uses dead edge " + std::to_string(e.index()));
      if (k.tail(loop[i]) != verts[i]) fail(2, f.index(), "vertex loop disagrees with edge loop at position " + std::to_string(i));
      if (k.head(loop[i]) != k.tail(loop[(i + 1) % loop.size()]))
        fail(2, f.index(), "loop is not closed after edge " + std::to_string(e.index()));
      if (!contains(k.edgeFaces(e), f)) fail(2, f.index(), "missing from the regions of edge " + std::to_string(e.index()));
    }
    sortedVertices(k, f, key);
    if (std::adjacent_find(key.begin(), key.end()) != key.end()) fail(2, f.index(), "loop passes twice through a vertex");
    if (duplicate_of[f.index()] != kInvalidIndex)
      fail(2, f.index(), "duplicates face " + std::to_string(duplicate_of[f.index()]));
    if (D == 3) {
      const auto vols = k.faceVolumes(f);
      if (vols.empty()) fail(2, f.index(), "dangling wall (bounds no cell)");
      if (vols.size() > 2) fail(2, f.index(), "bounds " + std::to_string(vols.size()) + " cells");
      for (VolumeId c : vols) {
        if (!k.alive(c)) fail(2, f.index(), "regions list dead volume " + std::to_string(c.index()));
        if (k.faceSign(c, f) == 0) fail(2, f.index(), "regions list volume " + std::to_string(c.index()) + " which it does not bound");
      }
      if (vols.size() == 2 && k.faceSign(vols[0], f) == k.faceSign(vols[1], f))
        fail(2, f.index(), "has the same orientation in both its cells " + std::to_string(vols[0].index()) + " and " +
                               std::to_string(vols[1].index()) + " (normals must point out of each)");
    }
  }
  if (D == 3) {
    for (VolumeId c : t.volumes()) {
      const auto faces = k.volumeFaces(c);
      if (faces.size() < 4) fail(3, c.index(), "has only " + std::to_string(faces.size()) + " faces");
      std::vector<std::pair<Index, int>> uses;
      for (OrientedFace of : faces) {
        if (!k.alive(of.handle())) fail(3, c.index(), "uses dead face " + std::to_string(of.handle().index()));
        if (!contains(k.faceVolumes(of.handle()), c))
          fail(3, c.index(), "missing from the regions of face " + std::to_string(of.handle().index()));
        for (OrientedEdge oe : k.faceEdges(of.handle()))
          uses.emplace_back(oe.handle().index(), oe.reversed() == of.reversed() ? 1 : -1);
      }
      std::sort(uses.begin(), uses.end());
      for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i;
        int fwd = 0, bwd = 0;
        for (; j < uses.size() && uses[j].first == uses[i].first; ++j) (uses[j].second > 0 ? fwd : bwd)++;
        if (fwd != 1 || bwd != 1)
          fail(3, c.index(), "surface is not closed and consistently oriented at edge " + std::to_string(uses[i].first) +
                                 " (used " + std::to_string(fwd) + " times forward, " + std::to_string(bwd) + " backward)");
        i = j;
      }
    }
  }
}

void checkOrientation2D(const Tissue& t) {
  const CellComplex& k = t.topology();
  for (EdgeId e : t.edges()) {
    const auto faces = k.edgeFaces(e);
    if (faces.size() != 2) continue;
    const bool r0 = k.faceEdges(faces[0])[k.loopPosition(faces[0], e)].reversed();
    const bool r1 = k.faceEdges(faces[1])[k.loopPosition(faces[1], e)].reversed();
    if (r0 == r1)
      fail(1, e.index(), "cells " + std::to_string(faces[0].index()) + " and " + std::to_string(faces[1].index()) +
                             " traverse it in the same direction (inconsistent orientation)");
  }
}

// Euler characteristic, per piece: cells connected through shared walls
// (edges in 2D, faces in 3D). Pieces that touch only at a vertex or along an
// edge are checked apart, each with its own copy of what they share, and so
// is a piece that touches itself there: a vertex (3D: also an edge) counts
// once per "umbrella", a set of the piece's cells around it connected through
// walls containing it. That is the characteristic of the piece with its
// pinch points pulled apart, which is a disk with b - 1 holes (2D: V-E+F =
// 2 - b, b boundary loops traced through the umbrellas) or a solid ball (3D:
// V-E+F-C = 1). For a tissue with no pinch points this is the usual count.
void checkEuler(const Tissue& t) {
  const CellComplex& k = t.topology();
  const int D = t.dim();
  const Index ncells = static_cast<Index>(t.cellSlots());
  UnionFind pieces(ncells);
  for (WallId w : t.walls()) {
    const auto cells = t.wallCells(w);
    for (std::size_t i = 1; i < cells.size(); ++i) pieces.unite(cells[0].index(), cells[i].index());
  }
  // Incidence nodes (cell, vertex) and, in 3D, (cell, edge); united across walls into umbrellas.
  std::unordered_map<std::uint64_t, Index> node_of;
  const auto key = [](Index cell, int degree, Index element) {
    return (static_cast<std::uint64_t>(cell) << 33) | (static_cast<std::uint64_t>(degree) << 32) |
           static_cast<std::uint64_t>(static_cast<std::uint32_t>(element));
  };
  std::vector<Index> node_piece;
  std::vector<int> node_degree;
  const auto node = [&](Index cell, int degree, Index element) {
    auto [it, fresh] = node_of.emplace(key(cell, degree, element), static_cast<Index>(node_piece.size()));
    if (fresh) {
      node_piece.push_back(pieces.find(cell));
      node_degree.push_back(degree);
    }
    return it->second;
  };
  const auto cellFaces = [&](CellId c) {
    std::vector<FaceId> faces;
    if (D == 2) faces.push_back(FaceId(c.index()));
    else
      for (OrientedFace of : k.volumeFaces(VolumeId(c.index()))) faces.push_back(of.handle());
    return faces;
  };
  std::unordered_map<Index, long> chi;
  for (CellId c : t.cells()) {
    chi[pieces.find(c.index())] += (D == 2 ? 1 : -1);
    for (FaceId f : cellFaces(c))
      for (OrientedEdge oe : k.faceEdges(f)) {
        node(c.index(), 0, k.tail(oe).index());
        if (D == 3) node(c.index(), 1, oe.handle().index());
      }
  }
  UnionFind umbrellas(node_piece.size());
  for (WallId w : t.walls()) {
    const auto cells = t.wallCells(w);
    if (cells.size() < 2) continue;
    const FaceId f(w.index());
    for (std::size_t i = 1; i < cells.size(); ++i) {
      const Index a = cells[0].index(), b = cells[i].index();
      if (D == 2) {
        for (VertexId v : k.edgeVertices(EdgeId(w.index()))) umbrellas.unite(node(a, 0, v.index()), node(b, 0, v.index()));
        continue;
      }
      for (OrientedEdge oe : k.faceEdges(f)) {
        umbrellas.unite(node(a, 0, k.tail(oe).index()), node(b, 0, k.tail(oe).index()));
        umbrellas.unite(node(a, 1, oe.handle().index()), node(b, 1, oe.handle().index()));
      }
    }
  }
  // Walls are counted once (each lies in one piece); in 2D the faces are the cells.
  if (D == 2) {
    for (EdgeId e : t.edges()) chi[pieces.find(k.edgeFaces(e)[0].index())] -= 1;
  } else {
    for (FaceId f : t.faces()) chi[pieces.find(k.faceVolumes(f)[0].index())] += 1;
  }
  for (std::size_t n = 0; n < node_piece.size(); ++n)
    if (umbrellas.find(static_cast<Index>(n)) == static_cast<Index>(n)) chi[node_piece[n]] += node_degree[n] == 0 ? 1 : -1;
  if (D == 3) {
    for (const auto& [piece, x] : chi)
      if (x != 1)
        fail(3, piece, "its piece (cells connected through walls) has Euler characteristic V-E+F-C = " +
                           std::to_string(x) + ", expected 1 for a solid ball (a tunnel, cavity or broken incidence?)");
    return;
  }
  // 2D: boundary loops are the components of the boundary edges joining the umbrellas of their ends.
  UnionFind loops_uf(node_piece.size());
  std::vector<std::uint8_t> on_boundary(node_piece.size(), 0);
  for (EdgeId e : t.edges()) {
    const auto faces = k.edgeFaces(e);
    if (faces.size() != 1) continue;
    const auto ev = k.edgeVertices(e);
    const Index a = umbrellas.find(node(faces[0].index(), 0, ev[0].index()));
    const Index b = umbrellas.find(node(faces[0].index(), 0, ev[1].index()));
    on_boundary[a] = on_boundary[b] = 1;
    loops_uf.unite(a, b);
  }
  std::unordered_map<Index, long> loops;
  for (std::size_t n = 0; n < node_piece.size(); ++n)
    if (on_boundary[n] && loops_uf.find(static_cast<Index>(n)) == static_cast<Index>(n)) loops[node_piece[n]] += 1;
  for (const auto& [piece, x] : chi) {
    const long b = loops.count(piece) ? loops[piece] : 0;
    if (x != 2 - b)
      fail(2, piece, "its piece (cells connected through walls) has Euler characteristic V-E+F = " +
                         std::to_string(x) + " with " + std::to_string(b) + " boundary loop(s); expected " +
                         std::to_string(2 - b) + " for a genus-0 sheet (a handle or broken incidence?)");
  }
}

void checkMeasures(const Tissue& t) {
  for (EdgeId e : t.edges())
    if (!(edgeLength(t, e) > 0)) fail(1, e.index(), "has zero length");
  int orientation = 0;
  for (FaceId f : t.faces()) {
    const PolygonMeasures m = polygonMeasures(t, f);
    if (!(m.area > 0)) fail(2, f.index(), "has non-positive area " + formatNumber(m.area, 6));
    if (t.embedding() == Embedding::Planar) {
      const int s = m.normal.z() > 0 ? 1 : -1;
      if (orientation == 0) orientation = s;
      else if (s != orientation)
        fail(2, f.index(), "is inverted: its loop turns the other way from the tissue's other cells");
    }
  }
  if (t.dim() == 3)
    for (VolumeId c : t.volumes()) {
      const double v = cellMeasure(t, CellId(c.index()));
      if (!(v > 0)) fail(3, c.index(), "has non-positive volume " + std::to_string(v));
    }
}

/// Every polygon (2D cell, 3D wall) is a simple closed curve in its best-fit
/// plane; in a curved sheet, no two neighbours fold onto each other.
void checkShapes(const Tissue& t, bool self_intersection) {
  const CellComplex& k = t.topology();
  std::vector<Vec3> loop;
  std::vector<Vec3> normals(t.dim() == 2 ? k.slots(2) : 0, Vec3::Zero());
  for (FaceId f : t.faces()) {
    const auto verts = k.faceVertices(f);
    loop.clear();
    for (VertexId v : verts) loop.push_back(t.position(v));
    const PolygonDefect d = polygonDefect(loop);
    const PolygonTriangulation surface = polygonTriangulation(loop);
    // A non-planar polygon whose fan from the vertex mean does not fold is
    // measured on that fan, whatever its projection: its outline is checked
    // in the best-fit plane only where the projection is what measures it.
    const bool projected = t.embedding() == Embedding::Planar || surface.folded;
    if (d.kind == PolygonDefect::Pinched || (self_intersection && d.kind == PolygonDefect::SelfIntersecting && projected))
      fail(2, f.index(), polygonDefectText(d, verts, loop));
    if (t.dim() == 2) normals[f.index()] = surface.normal;
  }
  if (t.dim() != 2 || t.embedding() != Embedding::Surface) return;
  // A cell folded over onto its neighbour (an inverted cell of a consistently
  // oriented sheet) turns its normal against the neighbour's.
  for (EdgeId e : t.edges()) {
    const auto faces = k.edgeFaces(e);
    if (faces.size() != 2) continue;
    if (normals[faces[0].index()].dot(normals[faces[1].index()]) < 0) {
      const auto ev = k.edgeVertices(e);
      fail(2, faces[1].index(),
           "overlaps its neighbour cell " + std::to_string(faces[0].index()) + ": their normals point opposite ways across wall " +
               std::to_string(e.index()) + " (vertices " + std::to_string(ev[0].index()) + " and " +
               std::to_string(ev[1].index()) + "); one of them is folded over or inverted");
    }
  }
}

}  // namespace

ValidationReport validate(const Tissue& t, const ValidateOptions& options) {
  try {
    checkIncidence(t);
    if (t.dim() == 2 && options.check_orientation) checkOrientation2D(t);
    if (options.check_euler) checkEuler(t);
    if (options.check_measures) checkMeasures(t);
    if (options.check_shapes) checkShapes(t, options.check_self_intersection);
  } catch (const Fail& f) {
    return f.report;
  }
  return {};
}

void validateOrThrow(const Tissue& t, const ValidateOptions& options) {
  const ValidationReport r = validate(t, options);
  if (!r) throw TopologyError("invalid tissue: " + r.message, r.element);
}

}  // namespace tessella
