// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The wall surfaces a planned 3D division would make, built as
// Tissue::splitCell will build their loops, and tested against each other and
// the walls around them with the mesher's pair test (division_crossings.hpp).

#include "tessella/growth/division_crossings.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::growth {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Tri = std::array<int, 3>;

// Points by id: the tissue's vertex slots, then the division's new vertices,
// then one centre per fan.
struct Points {
  std::vector<Vec3> p;
  K::Point_3 operator()(int i) const { return {p[i].x(), p[i].y(), p[i].z()}; }
};

// The surface of a loop of point ids, as the mesher triangulates the wall
// (mesh/src/geometry_check.cpp, triangulateWalls); `defect` is the outline
// defect the mesher refuses (pinched, or self-intersecting where the surface
// folds).
std::vector<Tri> surfaceOf(const std::vector<int>& loop, Points& pts, bool* defect = nullptr) {
  std::vector<Vec3> xyz(loop.size());
  for (std::size_t i = 0; i < loop.size(); ++i) xyz[i] = pts.p[loop[i]];
  const PolygonTriangulation s = polygonTriangulation(xyz);
  if (defect) {
    const PolygonDefect d = polygonDefect(xyz);
    *defect = d.kind == PolygonDefect::Pinched || (d.kind == PolygonDefect::SelfIntersecting && s.folded);
  }
  std::vector<Tri> tris;
  if (s.fan()) {
    const int centre = static_cast<int>(pts.p.size());
    pts.p.push_back(s.center);
    for (std::size_t i = 0; i < loop.size(); ++i) tris.push_back({centre, loop[i], loop[(i + 1) % loop.size()]});
  } else {
    for (const auto& t : s.triangles) tris.push_back({loop[t[0]], loop[t[1]], loop[t[2]]});
  }
  return tris;
}

// The mesher's test of two wall triangles: they may meet only at shared
// vertices and edges.
bool trianglesCross(const Points& P, const Tri& A, const Tri& B) {
  std::vector<int> shared;
  for (int a : A)
    if (std::find(B.begin(), B.end(), a) != B.end()) shared.push_back(a);
  const auto others = [&](const Tri& T) {
    std::vector<int> o;
    for (int v : T)
      if (std::find(shared.begin(), shared.end(), v) == shared.end()) o.push_back(v);
    return o;
  };
  if (shared.size() == 3) return true;
  if (shared.size() == 2) {
    const int r = others(A)[0], s = others(B)[0];
    return CGAL::coplanar(P(shared[0]), P(shared[1]), P(r), P(s)) &&
           CGAL::coplanar_orientation(P(shared[0]), P(shared[1]), P(r), P(s)) == CGAL::POSITIVE;
  }
  const K::Triangle_3 ta(P(A[0]), P(A[1]), P(A[2])), tb(P(B[0]), P(B[1]), P(B[2]));
  if (shared.size() == 1) {
    const auto oa = others(A), ob = others(B);
    return CGAL::do_intersect(tb, K::Segment_3(P(oa[0]), P(oa[1]))) ||
           CGAL::do_intersect(ta, K::Segment_3(P(ob[0]), P(ob[1])));
  }
  return CGAL::do_intersect(ta, tb);
}

struct Box {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  void add(const Vec3& x) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  bool overlaps(const Box& b) const { return !((lo.array() > b.hi.array()).any() || (b.lo.array() > hi.array()).any()); }
};

Box boxOf(const Points& P, const Tri& t) {
  Box b;
  for (int v : t) b.add(P.p[v]);
  return b;
}

// Whether two triangle lists cross (same = one list against itself).
bool surfacesCross(const Points& P, const std::vector<Tri>& a, const std::vector<Tri>& b, bool same) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = same ? i + 1 : 0; j < b.size(); ++j)
      if (boxOf(P, a[i]).overlaps(boxOf(P, b[j])) && trianglesCross(P, a[i], b[j])) return true;
  return false;
}

std::vector<int> loopIds(const Tissue& t, FaceId f) {
  std::vector<int> ids;
  for (VertexId v : t.topology().faceVertices(f)) ids.push_back(static_cast<int>(v.index()));
  return ids;
}

std::string cellsText(const Tissue& t, Index wall) {
  std::string s;
  for (CellId c : t.wallCells(WallId(wall))) s += (s.empty() ? "" : ", ") + std::to_string(c.index());
  return "(cells " + s + ")";
}

// A wall surface after the division: the new wall, a piece of a cut wall, or
// a wall given a new vertex; `wall` is the wall it comes from (invalid for the
// new wall).
struct Changed {
  enum Kind { NewWall, Piece, NewVertex } kind;
  Index wall;
  std::vector<int> loop;
  std::vector<Tri> tris;
};

std::string describe(const Tissue& t, const Changed& s) {
  switch (s.kind) {
    case Changed::NewWall: return "the new wall";
    case Changed::Piece: return "a piece of wall " + std::to_string(s.wall) + " " + cellsText(t, s.wall);
    case Changed::NewVertex: break;
  }
  return "wall " + std::to_string(s.wall) + " " + cellsText(t, s.wall) + " (given a vertex where the plane crosses it)";
}

}  // namespace

std::string divisionCrossing(const Tissue& t, CellId c, const CellSplitPlan3D& plan) {
  const CellComplex& cx = t.topology();
  Points pts;
  pts.p.assign(t.slots(0), Vec3::Zero());
  for (VertexId v : t.vertices()) pts.p[v.index()] = t.position(v);

  // The loops Tissue::splitCell will make: crossed edges split in ring order
  // (a new vertex goes between the edge's ends in every loop holding it), then
  // the crossed walls split between their two corners (the wall keeps the part
  // from the first corner to the second, the new wall the rest), then the cut.
  std::vector<Index> touched;
  std::vector<std::vector<int>> loops;
  const auto loopOf = [&](FaceId f) -> std::vector<int>& {
    const auto at = std::find(touched.begin(), touched.end(), f.index());
    if (at != touched.end()) return loops[static_cast<std::size_t>(at - touched.begin())];
    touched.push_back(f.index());
    loops.push_back(loopIds(t, f));
    return loops.back();
  };
  std::vector<int> corner(plan.ring.size());
  for (std::size_t i = 0; i < plan.ring.size(); ++i) {
    const CutNode& node = plan.ring[i];
    if (!node.isNew()) {
      corner[i] = static_cast<int>(node.vertex.index());
      continue;
    }
    corner[i] = static_cast<int>(pts.p.size());
    pts.p.push_back(node.point);
    const auto [a, b] = cx.edgeVertices(node.edge);
    const int ia = static_cast<int>(a.index()), ib = static_cast<int>(b.index());
    for (FaceId f : cx.edgeFaces(node.edge)) {
      std::vector<int>& loop = loopOf(f);
      const std::size_t n = loop.size();
      for (std::size_t p = 0; p < n; ++p) {
        const int u = loop[p], w = loop[(p + 1) % n];
        if ((u == ia && w == ib) || (u == ib && w == ia)) {
          loop.insert(loop.begin() + static_cast<std::ptrdiff_t>(p + 1), corner[i]);
          break;
        }
      }
    }
  }
  std::vector<Changed> changed;
  std::vector<Index> cut_walls;
  for (const auto& cut : plan.wall_cuts) {
    const std::vector<int>& loop = loopOf(cut.wall);
    const int n = static_cast<int>(loop.size());
    const int ia = static_cast<int>(std::find(loop.begin(), loop.end(), corner[cut.from]) - loop.begin());
    const int ib = static_cast<int>(std::find(loop.begin(), loop.end(), corner[cut.to]) - loop.begin());
    Changed keep{Changed::Piece, cut.wall.index(), {}, {}}, move = keep;
    for (int i = ia;; i = (i + 1) % n) {
      keep.loop.push_back(loop[i]);
      if (i == ib) break;
    }
    for (int i = ib;; i = (i + 1) % n) {
      move.loop.push_back(loop[i]);
      if (i == ia) break;
    }
    changed.push_back(std::move(keep));
    changed.push_back(std::move(move));
    cut_walls.push_back(cut.wall.index());
  }
  for (std::size_t k = 0; k < touched.size(); ++k)
    if (std::find(cut_walls.begin(), cut_walls.end(), touched[k]) == cut_walls.end())
      changed.push_back({Changed::NewVertex, touched[k], loops[k], {}});
  changed.push_back({Changed::NewWall, kInvalidIndex, corner, {}});

  // The old surfaces, for crossings that were there before the division.
  const auto oldCross = [&](Index a, Index b) {
    Points old = pts;
    const std::vector<Tri> ta = surfaceOf(loopIds(t, FaceId(a)), old);
    if (a == b) return surfacesCross(old, ta, ta, true);
    return surfacesCross(old, ta, surfaceOf(loopIds(t, FaceId(b)), old), false);
  };
  const auto oldDefect = [&](Index w) {
    Points old = pts;
    bool defect = false;
    surfaceOf(loopIds(t, FaceId(w)), old, &defect);
    return defect;
  };
  const std::string who = "dividing cell " + std::to_string(c.index()) + " (lineage " +
                          std::to_string(t.lineageId(c)) + ") by this plane would make ";

  Box changed_box;
  for (Changed& s : changed) {
    bool defect = false;
    s.tris = surfaceOf(s.loop, pts, &defect);
    if (defect && !(s.kind != Changed::NewWall && oldDefect(s.wall)))
      return who + describe(t, s) + " self-intersecting (its outline crosses itself in its best-fit plane)";
    for (const Tri& tri : s.tris) {
      const Box b = boxOf(pts, tri);
      changed_box.add(b.lo);
      changed_box.add(b.hi);
    }
  }
  const auto near = [&](const Tri& tri) { return " near " + formatPoint(pts.p[tri[1]], 9); };

  // Among themselves (a surface against itself too, as the mesher tests).
  for (std::size_t i = 0; i < changed.size(); ++i)
    for (std::size_t j = i; j < changed.size(); ++j) {
      const Changed &a = changed[i], &b = changed[j];
      for (std::size_t p = 0; p < a.tris.size(); ++p)
        for (std::size_t q = i == j ? p + 1 : 0; q < b.tris.size(); ++q) {
          if (!boxOf(pts, a.tris[p]).overlaps(boxOf(pts, b.tris[q])) || !trianglesCross(pts, a.tris[p], b.tris[q]))
            continue;
          const bool before = a.kind != Changed::NewWall && b.kind != Changed::NewWall && oldCross(a.wall, b.wall);
          if (before) continue;
          if (i == j) return who + describe(t, a) + " intersect itself" + near(a.tris[p]);
          return who + describe(t, a) + " cross " + describe(t, b) + near(a.tris[p]);
        }
    }

  // Against the unchanged walls of every cell sharing a vertex with a changed wall.
  std::vector<VertexId> around = t.cellVertices(c);
  for (Index w : touched)
    for (VertexId v : cx.faceVertices(FaceId(w))) around.push_back(v);
  std::vector<Index> cells;
  for (VertexId v : around)
    for (EdgeId e : cx.vertexEdges(v))
      for (FaceId f : cx.edgeFaces(e))
        for (VolumeId vol : cx.faceVolumes(f)) cells.push_back(vol.index());
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::vector<Index> walls;
  for (Index cell : cells)
    for (OrientedFace of : cx.volumeFaces(VolumeId(cell))) walls.push_back(of.handle().index());
  std::sort(walls.begin(), walls.end());
  walls.erase(std::unique(walls.begin(), walls.end()), walls.end());
  for (Index w : walls) {
    if (std::find(touched.begin(), touched.end(), w) != touched.end()) continue;
    const std::vector<int> loop = loopIds(t, FaceId(w));
    Box wall_box;
    for (int v : loop) wall_box.add(pts.p[v]);
    if (!wall_box.overlaps(changed_box)) continue;
    const std::vector<Tri> tris = surfaceOf(loop, pts);
    for (const Changed& s : changed)
      for (const Tri& a : s.tris)
        for (const Tri& b : tris) {
          if (!boxOf(pts, a).overlaps(boxOf(pts, b)) || !trianglesCross(pts, a, b)) continue;
          if (s.kind != Changed::NewWall && oldCross(s.wall, w)) continue;
          return who + describe(t, s) + " cross wall " + std::to_string(w) + " " + cellsText(t, w) + near(a);
        }
  }
  return {};
}

}  // namespace tessella::growth
