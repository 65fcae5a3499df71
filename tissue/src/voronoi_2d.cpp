// 2D Voronoi tissues: CGAL's Delaunay triangulation gives each seed its
// neighbours; the seed's cell is the domain polygon clipped by the bisector of
// every Delaunay neighbour (so walls are exactly the dual of Delaunay edges),
// and the cells' vertices are welded into one conforming complex.

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

// CGAL headers trip -Wnull-dereference in GCC 12 optimised builds (in CGAL's
// own code); silence it for them only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#pragma GCC diagnostic pop

#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/voronoi.hpp"
#include "voronoi_cells.hpp"
#include "voronoi_domain.hpp"
#include "voronoi_seed_checks.hpp"
#include "voronoi_weld.hpp"

namespace tessella {
namespace detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<Index, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using Point = Kernel::Point_2;

// Keeps the part of a convex polygon with n.x <= h; vertices within `on` of
// the line stay as they are, so a line through a vertex cuts no sliver.
void clipPolygon(std::vector<Vec2>& poly, std::vector<Vec2>& scratch, std::vector<double>& side,
                 const Vec2& n, double h, double on) {
  const std::size_t m = poly.size();
  side.resize(m);
  bool any_out = false;
  for (std::size_t k = 0; k < m; ++k) {
    side[k] = n.dot(poly[k]) - h;
    any_out |= side[k] > on;
  }
  if (!any_out) return;
  scratch.clear();
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t l = (k + 1) % m;
    const double sa = side[k], sb = side[l];
    if (sa <= on) scratch.push_back(poly[k]);
    if ((sa < -on && sb > on) || (sa > on && sb < -on))
      scratch.push_back(poly[k] + (poly[l] - poly[k]) * (sa / (sa - sb)));
  }
  poly.swap(scratch);
}

// Area-weighted centroid of a polygon (fan from its first vertex).
Vec2 polygonCentroid(const std::vector<Vec2>& poly) {
  double twice_area = 0;
  Vec2 c = Vec2::Zero();
  for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
    const Vec2 a = poly[k] - poly[0], b = poly[k + 1] - poly[0];
    const double w = a.x() * b.y() - a.y() * b.x();
    twice_area += w;
    c += w * (a + b) / 3;
  }
  return poly[0] + c / twice_area;
}

Delaunay triangulate(std::span<const Vec3> seeds, double duplicate_distance) {
  std::vector<std::pair<Point, Index>> points;
  points.reserve(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i)
    points.emplace_back(Point(seeds[i].x(), seeds[i].y()), static_cast<Index>(i));
  Delaunay dt;
  dt.insert(points.begin(), points.end());  // spatially sorted insertion

  if (dt.number_of_vertices() < seeds.size()) {  // exact duplicates were merged
    std::vector<std::uint8_t> kept(seeds.size(), 0);
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) kept[v->info()] = 1;
    for (std::size_t i = 0; i < seeds.size(); ++i)
      if (!kept[i]) throwDuplicate(seeds, i, dt.nearest_vertex(points[i].first)->info());
  }
  if (dt.dimension() < 2) {
    // Name the two extreme seeds of the line they are all on.
    std::size_t a = 0, b = 0;
    for (std::size_t i = 0; i < seeds.size(); ++i) {
      if (std::tie(seeds[i].x(), seeds[i].y()) < std::tie(seeds[a].x(), seeds[a].y())) a = i;
      if (std::tie(seeds[i].x(), seeds[i].y()) > std::tie(seeds[b].x(), seeds[b].y())) b = i;
    }
    throw InputError("all " + std::to_string(seeds.size()) + " seeds are collinear, from " +
                     describeSeed(a, seeds[a]) + " to " + describeSeed(b, seeds[b]) +
                     ": their Voronoi cells are strips, not a tissue");
  }
  // The nearest neighbour of every seed is a Delaunay neighbour.
  const double d2 = duplicate_distance * duplicate_distance;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto va = e->first->vertex(Delaunay::cw(e->second));
    const auto vb = e->first->vertex(Delaunay::ccw(e->second));
    if (CGAL::squared_distance(va->point(), vb->point()) < d2)
      throwDuplicate(seeds, va->info(), vb->info());
  }
  return dt;
}

}  // namespace

ClippedCells2 clipVoronoi2(std::span<const Vec3> seeds, const ConvexDomain2& domain,
                           double duplicate_tolerance, CellOutput output) {
  const Delaunay dt = triangulate(seeds, duplicate_tolerance * domain.scale);
  const std::size_t n = seeds.size();
  std::vector<Delaunay::Vertex_handle> handle(n);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) handle[v->info()] = v;

  const double on = kOnTolerance * domain.scale;
  const std::vector<Vec2> start =
      domain.is_rectangle ? domain.corners
                          : std::vector<Vec2>{domain.lo, {domain.hi.x(), domain.lo.y()}, domain.hi,
                                              {domain.lo.x(), domain.hi.y()}};
  ClippedCells2 out;
  out.centroids.resize(n);
  const bool complex = output == CellOutput::Complex;
  VertexWelder welder(Vec3(domain.lo.x(), domain.lo.y(), 0), kWeldTolerance * domain.scale,
                      complex ? 2 * n + domain.corners.size() : 0);
  if (complex) out.polygons.resize(n);

  std::vector<Vec2> poly, scratch;
  std::vector<double> side;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 s(seeds[i].x(), seeds[i].y());
    poly = start;
    auto circ = dt.incident_vertices(handle[i]), done = circ;
    do {
      if (dt.is_infinite(circ)) continue;
      const Vec2 t(circ->point().x(), circ->point().y());
      const Vec2 d = t - s;
      const Vec2 normal = d / d.norm();
      clipPolygon(poly, scratch, side, normal, normal.dot((s + t) / 2), on);
    } while (++circ != done);
    if (!domain.is_rectangle) {
      // Only cells reaching past the polygon's inscribed circle meet its sides.
      double reach = 0;
      for (const Vec2& p : poly) reach = std::max(reach, (p - s).norm());
      if ((s - domain.center).norm() + reach >= domain.inner_radius) {
        for (const HalfPlane& hp : domain.sides)
          if (hp.offset - hp.normal.dot(s) < reach + on)
            clipPolygon(poly, scratch, side, hp.normal, hp.offset, on);
      }
    }
    if (poly.size() < 3)
      throw GeometryError("the Voronoi cell of " + describeSeed(i, seeds[i]) +
                          " vanished when clipped to the domain");
    const Vec2 c = polygonCentroid(poly);
    out.centroids[i] = Vec3(c.x(), c.y(), 0);
    if (!complex) continue;

    std::vector<Index>& loop = out.polygons[i];
    loop.reserve(poly.size());
    for (const Vec2& p : poly) {
      const Index v = welder.weld(Vec3(p.x(), p.y(), 0));
      if (loop.empty() || loop.back() != v) loop.push_back(v);
    }
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    if (loop.size() < 3)
      throw GeometryError("the Voronoi cell of " + describeSeed(i, seeds[i]) +
                          " collapsed to fewer than 3 vertices when its vertices were welded");
  }
  out.positions = welder.takePositions();
  return out;
}

}  // namespace detail

namespace {

template <typename Domain>
Tissue planarVoronoi(std::span<const Vec3> seeds, const Domain& d, const VoronoiOptions& options) {
  detail::checkOptions(options);
  const detail::ConvexDomain2 domain = detail::makeDomain(d);
  detail::checkSeeds2(seeds, domain);
  std::vector<Vec3> relaxed;
  if (options.lloyd_iterations > 0) {
    relaxed = detail::lloydRelax(seeds, domain, options.lloyd_iterations, options.duplicate_tolerance);
    seeds = relaxed;
  }
  detail::ClippedCells2 cells =
      detail::clipVoronoi2(seeds, domain, options.duplicate_tolerance, detail::CellOutput::Complex);
  return buildPolygonTissue(cells.positions, cells.polygons, Embedding::Planar);
}

}  // namespace

Tissue voronoiTissue(std::span<const Vec3> seeds, const Rectangle& domain,
                     const VoronoiOptions& options) {
  return planarVoronoi(seeds, domain, options);
}

Tissue voronoiTissue(std::span<const Vec3> seeds, const Disk& domain, const VoronoiOptions& options) {
  return planarVoronoi(seeds, domain, options);
}

}  // namespace tessella
