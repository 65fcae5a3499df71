// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The wall surfaces a planned 3D division would make, built as
// Tissue::splitCell will build their loops, and tested against each other and
// the walls around them with the mesher's pair test (tessella/mesh/triangle_pair.hpp).

#include "tessella/growth/division_crossings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "tessella/mesh/triangle_pair.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::growth {

namespace {

using Tri = mesh::TriangleIds;

// Points by local id: the tissue's vertices as they are met, the division's
// new vertices, one centre per fan.
struct Points {
  const Tissue& t;
  std::vector<Vec3> p;
  std::unordered_map<Index, int> of_vertex;
  int add(const Vec3& x) {
    p.push_back(x);
    return static_cast<int>(p.size() - 1);
  }
  int vertex(VertexId v) {
    const auto [at, fresh] = of_vertex.try_emplace(v.index(), static_cast<int>(p.size()));
    if (fresh) p.push_back(t.position(v));
    return at->second;
  }
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
    *defect =
        d.kind == PolygonDefect::Pinched || (d.kind == PolygonDefect::SelfIntersecting && s.folded);
  }
  std::vector<Tri> tris;
  if (s.fan()) {
    const int centre = pts.add(s.center);
    for (std::size_t i = 0; i < loop.size(); ++i)
      tris.push_back({centre, loop[i], loop[(i + 1) % loop.size()]});
  } else {
    for (const auto& t : s.triangles) tris.push_back({loop[t[0]], loop[t[1]], loop[t[2]]});
  }
  return tris;
}

// Boxes of triangles and surfaces, for the broad phase.
using Box = Eigen::AlignedBox3d;

Box boxOf(const Points& P, const Tri& t) {
  Box b;
  for (int v : t) b.extend(P.p[v]);
  return b;
}

// A wall's triangles with their boxes, and the box of them all.
struct Surface {
  std::vector<Tri> tris;
  std::vector<Box> boxes;
  Box box;
  Surface() = default;
  Surface(const Points& P, std::vector<Tri> triangles) : tris(std::move(triangles)) {
    for (const Tri& t : tris) {
      boxes.push_back(boxOf(P, t));
      box.extend(boxes.back());
    }
  }
};

// The first crossing pair of triangles (a's index), or -1 (same = one surface against itself).
long firstCrossing(const Points& P, const Surface& a, const Surface& b, bool same) {
  if (!a.box.intersects(b.box)) return -1;
  for (std::size_t i = 0; i < a.tris.size(); ++i) {
    if (!a.boxes[i].intersects(b.box)) continue;
    for (std::size_t j = same ? i + 1 : 0; j < b.tris.size(); ++j)
      if (a.boxes[i].intersects(b.boxes[j]) && mesh::trianglesCross(P.p, a.tris[i], b.tris[j]))
        return static_cast<long>(i);
  }
  return -1;
}

std::vector<int> loopIds(const Tissue& t, FaceId f, Points& P) {
  std::vector<int> ids;
  for (VertexId v : t.topology().faceVertices(f)) ids.push_back(P.vertex(v));
  return ids;
}

std::string cellsText(const Tissue& t, Index wall) {
  std::string s;
  for (CellId c : t.wallCells(WallId(wall)))
    s += (s.empty() ? "" : ", ") + std::to_string(c.index());
  return "(cells " + s + ")";
}

// A wall surface after the division: the new wall, a piece of a cut wall, or
// a wall given a new vertex; `wall` is the wall it comes from (invalid for the
// new wall).
struct Changed {
  enum Kind { NewWall, Piece, NewVertex } kind;
  Index wall;
  std::vector<int> loop;
  Surface surface;
};

std::string describe(const Tissue& t, const Changed& s) {
  switch (s.kind) {
    case Changed::NewWall:
      return "the new wall";
    case Changed::Piece:
      return "a piece of wall " + std::to_string(s.wall) + " " + cellsText(t, s.wall);
    case Changed::NewVertex:
      break;
  }
  return "wall " + std::to_string(s.wall) + " " + cellsText(t, s.wall) +
         " (given a vertex where the plane crosses it)";
}

// A flat convex polygon (to `tol`), and its unit normal (loop order).
bool flatConvex(const Tissue& t, FaceId f, double tol, Vec3& normal) {
  const auto loop = t.topology().faceVertices(f);
  const std::size_t n = loop.size();
  Vec3 area = Vec3::Zero();
  const Vec3& o = t.position(loop[0]);
  for (std::size_t i = 1; i + 1 < n; ++i)
    area += (t.position(loop[i]) - o).cross(t.position(loop[i + 1]) - o);
  if (!(area.norm() > 0)) return false;
  normal = area.normalized();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 &a = t.position(loop[i]), &b = t.position(loop[(i + 1) % n]),
               &d = t.position(loop[(i + 2) % n]);
    if (std::abs(normal.dot(a - o)) > tol) return false;
    if (normal.dot((b - a).cross(d - b)) < -tol * (d - b).norm()) return false;
  }
  return true;
}

// A convex cell with flat convex walls, whose crossed edges' other walls are
// flat and convex too: the division keeps every wall's point set (a flat
// convex polygon's fan covers it from any centre inside) and adds a wall
// inside the cell, so no wall can come to cross another (to `tol`).
bool cannotCross(const Tissue& t, CellId c, const CellSplitPlan3D& plan) {
  const CellComplex& cx = t.topology();
  const std::vector<VertexId> vertices = t.cellVertices(c);
  Box box;
  for (VertexId v : vertices) box.extend(t.position(v));
  const double tol = 1e-9 * box.diagonal().norm();
  const auto faces = cx.volumeFaces(VolumeId(c.index()));
  for (OrientedFace of : faces) {
    Vec3 normal;
    if (!flatConvex(t, of.handle(), tol, normal)) return false;
    const Vec3 outward = of.sign() * normal;
    const Vec3& o = t.position(cx.faceVertices(of.handle())[0]);
    for (VertexId v : vertices)
      if (outward.dot(t.position(v) - o) > tol) return false;
  }
  for (const CutNode& node : plan.ring) {
    if (!node.isNew()) continue;
    for (FaceId f : cx.edgeFaces(node.edge)) {
      Vec3 normal;
      if (std::none_of(faces.begin(), faces.end(),
                       [&](OrientedFace of) { return of.handle() == f; }) &&
          !flatConvex(t, f, tol, normal))
        return false;
    }
  }
  return true;
}

}  // namespace

std::string divisionCrossing(const Tissue& t, CellId c, const CellSplitPlan3D& plan) {
  if (cannotCross(t, c, plan)) return {};
  const CellComplex& cx = t.topology();
  Points pts{t, {}, {}};

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
    loops.push_back(loopIds(t, f, pts));
    return loops.back();
  };
  std::vector<int> corner(plan.ring.size());
  for (std::size_t i = 0; i < plan.ring.size(); ++i) {
    const CutNode& node = plan.ring[i];
    if (!node.isNew()) {
      corner[i] = pts.vertex(node.vertex);
      continue;
    }
    corner[i] = pts.add(node.point);
    const auto [a, b] = cx.edgeVertices(node.edge);
    const int ia = pts.vertex(a), ib = pts.vertex(b);
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
    const int ia =
        static_cast<int>(std::find(loop.begin(), loop.end(), corner[cut.from]) - loop.begin());
    const int ib =
        static_cast<int>(std::find(loop.begin(), loop.end(), corner[cut.to]) - loop.begin());
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
    const Surface sa(pts, surfaceOf(loopIds(t, FaceId(a), pts), pts));
    if (a == b) return firstCrossing(pts, sa, sa, true) >= 0;
    return firstCrossing(pts, sa, Surface(pts, surfaceOf(loopIds(t, FaceId(b), pts), pts)),
                         false) >= 0;
  };
  const auto oldDefect = [&](Index w) {
    bool defect = false;
    surfaceOf(loopIds(t, FaceId(w), pts), pts, &defect);
    return defect;
  };
  const std::string who = "dividing cell " + std::to_string(c.index()) + " (lineage " +
                          std::to_string(t.lineageId(c)) + ") by this plane would make ";

  Box changed_box;
  for (Changed& s : changed) {
    bool defect = false;
    s.surface = Surface(pts, surfaceOf(s.loop, pts, &defect));
    if (defect && !(s.kind != Changed::NewWall && oldDefect(s.wall)))
      return who + describe(t, s) +
             " self-intersecting (its outline crosses itself in its best-fit plane)";
    changed_box.extend(s.surface.box);
  }
  const auto near = [&](const Changed& s, long tri) {
    return " near " + formatPoint(pts.p[s.surface.tris[tri][1]], 9);
  };

  // Among themselves (a surface against itself too, as the mesher tests).
  for (std::size_t i = 0; i < changed.size(); ++i)
    for (std::size_t j = i; j < changed.size(); ++j) {
      const Changed &a = changed[i], &b = changed[j];
      const long at = firstCrossing(pts, a.surface, b.surface, i == j);
      if (at < 0) continue;
      if (a.kind != Changed::NewWall && b.kind != Changed::NewWall && oldCross(a.wall, b.wall))
        continue;
      if (i == j) return who + describe(t, a) + " intersect itself" + near(a, at);
      return who + describe(t, a) + " cross " + describe(t, b) + near(a, at);
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
    Box wall_box;
    for (VertexId v : cx.faceVertices(FaceId(w))) wall_box.extend(t.position(v));
    if (!wall_box.intersects(changed_box)) continue;
    const Surface other(pts, surfaceOf(loopIds(t, FaceId(w), pts), pts));
    for (const Changed& s : changed) {
      const long at = firstCrossing(pts, s.surface, other, false);
      if (at < 0 || (s.kind != Changed::NewWall && oldCross(s.wall, w))) continue;
      return who + describe(t, s) + " cross wall " + std::to_string(w) + " " + cellsText(t, w) +
             near(s, at);
    }
  }
  return {};
}

}  // namespace tessella::growth
