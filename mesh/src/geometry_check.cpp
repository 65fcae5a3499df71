// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The geometry check run before every mesher: degenerate, inverted and
// self-intersecting input is reported with element ids instead of reaching
// CGAL or TetGen (TetGen aborts, or worse, silently meshes the wrong region).

#include "tessella/mesh/geometry_check.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "polygon_fan.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/mesh/triangle_pair.hpp"
#include "tessella/tissue/geometry.hpp"
#include "wall_triangulation.hpp"

namespace tessella::mesh {
namespace detail {

double edgeLengthOf(const Tissue& t, EdgeId e);

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// Where a defect is (nine digits tell neighbouring vertices apart) and how small it is (computed: six digits).
std::string str(const Vec3& p) { return formatPoint(p, 9); }
std::string num(double x) { return formatNumber(x, 6); }

MeshabilityReport defect(const std::string& message, ElementId element) {
  return MeshabilityReport{false, message, element};
}

/// Uniform-grid broad phase: calls test(i, j) once for every pair of boxes
/// that overlap, i < j. Boxes are {min, max}.
template <typename Test>
bool forOverlappingPairs(const std::vector<std::array<Vec3, 2>>& boxes, const Test& test) {
  if (boxes.empty()) return true;
  Vec3 lo = boxes[0][0], hi = boxes[0][1];
  double mean_extent = 0.0;
  for (const auto& b : boxes) {
    lo = lo.cwiseMin(b[0]);
    hi = hi.cwiseMax(b[1]);
    mean_extent += (b[1] - b[0]).maxCoeff();
  }
  mean_extent /= static_cast<double>(boxes.size());
  const double span = (hi - lo).maxCoeff();
  // Cells about the size of an element, but at most ~256 per axis.
  const double h = std::max({mean_extent, span / 256.0, 1e-300});
  const auto cellOf = [&](const Vec3& p) {
    return std::array<long, 3>{static_cast<long>(std::floor((p.x() - lo.x()) / h)),
                               static_cast<long>(std::floor((p.y() - lo.y()) / h)),
                               static_cast<long>(std::floor((p.z() - lo.z()) / h))};
  };
  const auto key = [](const std::array<long, 3>& c) {
    return (static_cast<std::uint64_t>(c[0]) * 73856093ull) ^ (static_cast<std::uint64_t>(c[1]) * 19349663ull) ^
           (static_cast<std::uint64_t>(c[2]) * 83492791ull);
  };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  std::vector<std::array<long, 3>> first(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const auto a = cellOf(boxes[i][0]), b = cellOf(boxes[i][1]);
    first[i] = a;
    for (long x = a[0]; x <= b[0]; ++x)
      for (long y = a[1]; y <= b[1]; ++y)
        for (long z = a[2]; z <= b[2]; ++z) grid[key({x, y, z})].push_back(static_cast<int>(i));
  }
  for (const auto& [k, items] : grid) {
    for (std::size_t p = 0; p < items.size(); ++p) {
      for (std::size_t q = p + 1; q < items.size(); ++q) {
        const int i = std::min(items[p], items[q]), j = std::max(items[p], items[q]);
        const auto& bi = boxes[i];
        const auto& bj = boxes[j];
        if ((bi[0].array() > bj[1].array()).any() || (bj[0].array() > bi[1].array()).any()) continue;
        // Test each pair in one bucket only: the one holding the overlap's low corner.
        const auto c = cellOf(bi[0].cwiseMax(bj[0]));
        if (key(c) != k) continue;
        if (!test(i, j)) return false;
      }
    }
  }
  return true;
}

K::Point_2 p2(const Vec3& p) { return {p.x(), p.y()}; }

double loopPerimeter(const std::vector<Vec3>& loop) {
  double perimeter = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) perimeter += (loop[(i + 1) % loop.size()] - loop[i]).norm();
  return perimeter;
}

/// A polygon is degenerate when it is thinner than the length tolerance:
/// its mean width 2 * area / perimeter (the width of a sliver) is compared,
/// not its area, so small but well-shaped walls of a large tissue pass.
bool tooThin(double area, double perimeter, double tol) { return !(2.0 * area > tol * perimeter); }

/// A cell's outline must be a simple closed curve in its best-fit plane (a
/// pinched cell made CGAL's constrained triangulation fail a precondition).
MeshabilityReport checkOutline(const Tissue& t, CellId c, const std::vector<Vec3>& loop) {
  const PolygonDefect d = polygonDefect(loop);
  // As validate(): a self-intersecting projection matters only where the
  // projection measures the cell (planar, or a folded fan).
  if (!(d.kind == PolygonDefect::Pinched ||
        (d.kind == PolygonDefect::SelfIntersecting &&
         (t.embedding() == Embedding::Planar || polygonTriangulation(loop).folded))))
    return {};
  return defect("cell " + std::to_string(c.index()) + " " +
                    polygonDefectText(d, t.topology().faceVertices(t.cellFace(c)), loop),
                ElementId{2, c.index()});
}

MeshabilityReport checkEdges(const Tissue& t, double tol) {
  // First: a non-finite position makes the tissue's scale, and with it every
  // tolerance, infinite or NaN, and an unrelated edge would get the blame.
  for (VertexId v : t.vertices()) {
    const Vec3& p = t.position(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return defect("vertex " + std::to_string(v.index()) + " has the non-finite position " + str(p),
                    ElementId{0, v.index()});
  }
  const auto& topo = t.topology();
  for (EdgeId e : t.edges()) {
    const double len = edgeLengthOf(t, e);
    if (!(len > tol)) {
      const auto [a, b] = topo.edgeVertices(e);
      return defect("edge " + std::to_string(e.index()) + " between vertices " + std::to_string(a.index()) +
                        " and " + std::to_string(b.index()) + " has zero length (" + num(len) +
                        ") at " + str(t.position(a)) + "; coincident vertices cannot be meshed",
                    ElementId{1, e.index()});
    }
  }
  return {};
}

/// 2D planar tissues: z = 0, counter-clockwise cells, no crossing walls.
MeshabilityReport checkPlanar(const Tissue& t, double tol) {
  for (VertexId v : t.vertices())
    if (std::abs(t.position(v).z()) > tol)
      return defect("vertex " + std::to_string(v.index()) + " of a planar tissue is off the z = 0 plane: " +
                        str(t.position(v)),
                    ElementId{0, v.index()});
  for (CellId c : t.cells()) {
    const auto loop = loopPositions(t, t.cellFace(c));
    const double signed_area = fanVectorArea(loop, loopMean(loop)).z();
    if (signed_area < 0.0)
      return defect("cell " + std::to_string(c.index()) + " is inverted: its loop runs clockwise (signed area " +
                        num(signed_area) + ")",
                    ElementId{2, c.index()});
    if (tooThin(signed_area, loopPerimeter(loop), tol))
      return defect("cell " + std::to_string(c.index()) + " has zero area (" + num(signed_area) +
                        "; thinner than the tolerance " + num(tol) + ")",
                    ElementId{2, c.index()});
    if (auto r = checkOutline(t, c, loop); !r) return r;
  }
  // Wall edges may meet only at shared vertices.
  const auto& topo = t.topology();
  std::vector<EdgeId> edges(t.edges().begin(), t.edges().end());
  std::vector<std::array<Vec3, 2>> boxes;
  boxes.reserve(edges.size());
  for (EdgeId e : edges) {
    const Vec3& a = t.position(topo.edgeFrom(e));
    const Vec3& b = t.position(topo.edgeTo(e));
    boxes.push_back({a.cwiseMin(b), a.cwiseMax(b)});
  }
  MeshabilityReport report;
  forOverlappingPairs(boxes, [&](int i, int j) {
    const auto [a0, a1] = topo.edgeVertices(edges[i]);
    const auto [b0, b1] = topo.edgeVertices(edges[j]);
    const K::Point_2 pa0 = p2(t.position(a0)), pa1 = p2(t.position(a1));
    const K::Point_2 pb0 = p2(t.position(b0)), pb1 = p2(t.position(b1));
    bool bad = false;
    VertexId shared, oa, ob;
    if (a0 == b0 || a0 == b1) shared = a0, oa = a1, ob = (a0 == b0 ? b1 : b0);
    else if (a1 == b0 || a1 == b1) shared = a1, oa = a0, ob = (a1 == b0 ? b1 : b0);
    if (shared.valid()) {
      // Two edges from one vertex overlap only if they leave it in the same direction.
      const K::Point_2 s = p2(t.position(shared)), x = p2(t.position(oa)), y = p2(t.position(ob));
      bad = CGAL::orientation(s, x, y) == CGAL::COLLINEAR && (x - s) * (y - s) > 0;
    } else {
      bad = CGAL::do_intersect(K::Segment_2(pa0, pa1), K::Segment_2(pb0, pb1));
    }
    if (!bad) return true;
    report = defect("walls (edges) " + std::to_string(edges[i].index()) + " [" + str(t.position(a0)) + " - " +
                        str(t.position(a1)) + "] and " + std::to_string(edges[j].index()) + " [" +
                        str(t.position(b0)) + " - " + str(t.position(b1)) +
                        "] intersect: self-intersecting or overlapping cells",
                    ElementId{1, edges[i].index()});
    return false;
  });
  return report;
}

/// Curved sheets: each cell's outline is a simple closed curve in its
/// best-fit plane, and the surface the tissue measures it on (its fan, or
/// where that folds the triangulation of its outline) is what the mesh
/// reproduces.
MeshabilityReport checkSurface(const Tissue& t, double tol) {
  for (CellId c : t.cells()) {
    const auto loop = loopPositions(t, t.cellFace(c));
    const double area = polygonMeasures(loop).area;
    if (tooThin(area, loopPerimeter(loop), tol))
      return defect("cell " + std::to_string(c.index()) + " has zero area (" + num(area) +
                        "; thinner than the tolerance " + num(tol) + ")",
                    ElementId{2, c.index()});
    if (auto r = checkOutline(t, c, loop); !r) return r;
  }
  return {};
}

}  // namespace

std::string wallCellsText(const Tissue& t, WallId w) {
  std::string s;
  for (CellId c : t.wallCells(w)) s += (s.empty() ? "" : ", ") + std::to_string(c.index());
  return "(cells " + s + ")";
}

double tissueScale(const Tissue& t) {
  bool any = false;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  for (VertexId v : t.vertices()) {
    const Vec3& p = t.position(v);
    lo = any ? lo.cwiseMin(p) : p;
    hi = any ? hi.cwiseMax(p) : p;
    any = true;
  }
  return (hi - lo).norm();
}

double edgeLengthOf(const Tissue& t, EdgeId e) {
  const auto [a, b] = t.topology().edgeVertices(e);
  return (t.position(b) - t.position(a)).norm();
}

MeshabilityReport triangulateWalls(const Tissue& t, double tolerance, WallTriangulation& out) {
  const double scale = tissueScale(t);
  const double tol = tolerance * scale;
  out.vertex_slots = t.slots(0);
  out.points.assign(t.slots(0) + t.slots(2), Vec3::Zero());
  for (VertexId v : t.vertices()) out.points[v.index()] = t.position(v);
  out.wall_triangles.assign(t.slots(2), {});
  out.wall_planar.assign(t.slots(2), 0);
  out.wall_normal.assign(t.slots(2), Vec3::Zero());
  for (WallId w : t.walls()) {
    const FaceId f = handle_cast<FaceId>(w);
    const auto verts = t.topology().faceVertices(f);
    const auto loop = loopPositions(t, f);
    const FanSurface fan = fanSurface(loop);
    if (tooThin(fan.area, loopPerimeter(loop), tol))
      return defect("wall " + std::to_string(w.index()) + " " + wallCellsText(t, w) + " has zero area (" +
                        num(fan.area) + "; thinner than the tolerance " + num(tol) + ")",
                    ElementId{2, w.index()});
    const PolygonDefect d = polygonDefect(loop);
    if (d.kind == PolygonDefect::Pinched ||
        (d.kind == PolygonDefect::SelfIntersecting && polygonTriangulation(loop).folded))
      return defect("wall " + std::to_string(w.index()) + " " + wallCellsText(t, w) + " " +
                        polygonDefectText(d, verts, loop),
                    ElementId{2, w.index()});
    out.wall_normal[w.index()] = fan.normal;
    out.wall_planar[w.index()] = fan.planarity_deviation <= tol;
    // The surface the tissue measures the wall on: its fan (from the vertex
    // mean, or where that folds from its kernel's centroid), or the
    // triangulation of its outline (tissue/geometry.hpp).
    const PolygonTriangulation surface = polygonTriangulation(loop);
    out.points[out.centerPoint(w)] = surface.center;
    auto& tris = out.wall_triangles[w.index()];
    if (surface.fan()) {
      for (std::size_t i = 0; i < verts.size(); ++i)
        tris.push_back({out.centerPoint(w), static_cast<int>(verts[i].index()),
                        static_cast<int>(verts[(i + 1) % verts.size()].index())});
    } else {
      for (const auto& tri : surface.triangles)
        tris.push_back({static_cast<int>(verts[tri[0]].index()), static_cast<int>(verts[tri[1]].index()),
                        static_cast<int>(verts[tri[2]].index())});
    }
  }
  return {};
}

MeshabilityReport checkVolumeGeometry(const Tissue& t, const MeshOptions& options, WallTriangulation& walls) {
  const double scale = tissueScale(t);
  const double tol = options.tolerance * scale;
  if (auto r = checkEdges(t, tol); !r) return r;
  if (auto r = triangulateWalls(t, options.tolerance, walls); !r) return r;
  // Cell volumes by the divergence theorem over the same triangles.
  const auto& topo = t.topology();
  for (CellId c : t.cells()) {
    const VolumeId vol = handle_cast<VolumeId>(c);
    double volume = 0.0, surface = 0.0;
    for (OrientedFace of : topo.volumeFaces(vol))
      for (const auto& tri : walls.wall_triangles[of.handle().index()]) {
        const Vec3 &a = walls.points[tri[0]], &b = walls.points[tri[1]], &d = walls.points[tri[2]];
        volume += of.sign() * a.dot(b.cross(d)) / 6.0;
        surface += 0.5 * (b - a).cross(d - a).norm();
      }
    if (volume < 0.0)
      return defect("cell " + std::to_string(c.index()) + " is inverted: its volume is negative (signed volume " +
                        num(volume) + ")",
                    ElementId{3, c.index()});
    // Mean thickness 2 * volume / surface, as for polygons: a flat cell fails, a small one passes.
    if (!(2.0 * volume > tol * surface))
      return defect("cell " + std::to_string(c.index()) + " has zero volume (" + num(volume) +
                        "; thinner than the tolerance " + num(tol) + ")",
                    ElementId{3, c.index()});
  }
  // Wall triangles may meet only at shared vertices and edges (triangle_pair.hpp).
  struct Tri {
    WallId wall;
    std::array<int, 3> v;
  };
  std::vector<Tri> tris;
  std::vector<std::array<Vec3, 2>> boxes;
  for (WallId w : t.walls())
    for (const auto& tri : walls.wall_triangles[w.index()]) {
      tris.push_back({w, tri});
      const Vec3 &a = walls.points[tri[0]], &b = walls.points[tri[1]], &c = walls.points[tri[2]];
      boxes.push_back({a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)});
    }
  MeshabilityReport report;
  forOverlappingPairs(boxes, [&](int i, int j) {
    const auto& A = tris[i].v;
    const auto& B = tris[j].v;
    const bool bad = trianglesCross(walls.points, A, B);
    if (!bad) return true;
    const WallId wa = tris[i].wall, wb = tris[j].wall;
    if (wa == wb)
      report = defect("wall " + std::to_string(wa.index()) + " " + wallCellsText(t, wa) +
                          " intersects itself near " + str(walls.points[A[1]]),
                      ElementId{2, wa.index()});
    else
      report = defect("walls " + std::to_string(wa.index()) + " " + wallCellsText(t, wa) + " and " +
                          std::to_string(wb.index()) + " " + wallCellsText(t, wb) + " intersect near " +
                          str(walls.points[A[1]]) + ": self-intersecting or overlapping cells",
                      ElementId{2, wa.index()});
    return false;
  });
  return report;
}

}  // namespace detail

MeshabilityReport findGeometryDefects(const Tissue& tissue, const MeshOptions& options) {
  using namespace detail;
  const double scale = tissueScale(tissue);
  const double tol = options.tolerance * scale;
  if (tissue.numCells() == 0) return defect("the tissue has no cells to mesh", {});
  if (tissue.dim() == 3) {
    WallTriangulation walls;
    return checkVolumeGeometry(tissue, options, walls);
  }
  if (auto r = checkEdges(tissue, tol); !r) return r;
  return tissue.embedding() == Embedding::Planar ? checkPlanar(tissue, tol)
                                                  : checkSurface(tissue, tol);
}

void checkMeshable(const Tissue& tissue, const MeshOptions& options) {
  const MeshabilityReport report = findGeometryDefects(tissue, options);
  if (!report) throw GeometryError("cannot mesh the tissue: " + report.message, report.element);
}

}  // namespace tessella::mesh
