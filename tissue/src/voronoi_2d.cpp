// 2D Voronoi tissues from CGAL's Delaunay triangulation. Voronoi vertices are
// the circumcentres of Delaunay triangles (triangles whose circumcentres lie
// within the weld tolerance, e.g. 4 cocircular seeds, are one vertex). A cell
// whose triangles' circumcentres all lie inside the domain is read off its
// triangles directly; only the cells reaching the boundary are clipped (the
// domain cut by the bisector of every Delaunay neighbour) and their vertices
// welded onto those circumcentres, so walls are exactly the dual of Delaunay
// edges. Per-cell work runs in parallel; numbering is sequential, so the
// result does not depend on the thread count.

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <omp.h>

// CGAL headers trip -Wnull-dereference in GCC 12 optimised builds (in CGAL's
// own code); silence it for them only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
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
using FaceBase = CGAL::Triangulation_face_base_with_info_2<Index, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
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

Delaunay triangulate(std::span<const Vec3> seeds) {
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
  // Seeds closer than duplicate_distance are found among Delaunay neighbours
  // (the nearest neighbour of every seed is one) by clipVoronoi2.
  return dt;
}

}  // namespace

ClippedCells2 clipVoronoi2(std::span<const Vec3> seeds, const ConvexDomain2& domain,
                           double duplicate_tolerance, CellOutput output) {
  Delaunay dt = triangulate(seeds);
  const std::size_t n = seeds.size();
  std::vector<Delaunay::Vertex_handle> handle(n);
  // Seeds in CGAL's storage order (along its Hilbert sort): cells visited in
  // this order touch nearby memory one after the other.
  std::vector<Index> order;
  order.reserve(n);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    handle[v->info()] = v;
    order.push_back(v->info());
  }

  // Finite triangles numbered in CGAL's (deterministic) order, with their circumcentres.
  std::vector<Delaunay::Face_handle> tri;
  tri.reserve(2 * n);
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info() = kInvalidIndex;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    f->info() = static_cast<Index>(tri.size());
    tri.push_back(f);
  }
  // A cell is interior when all its triangles are finite and their circumcentres
  // lie inside the domain by a margin far above the clipping tolerances.
  const double margin = kInteriorMargin * domain.scale;
  auto inside = [&](const Vec2& p) {
    if (domain.is_rectangle)
      return p.x() > domain.lo.x() + margin && p.x() < domain.hi.x() - margin &&
             p.y() > domain.lo.y() + margin && p.y() < domain.hi.y() - margin;
    if ((p - domain.center).norm() < domain.inner_radius - margin) return true;
    return domain.excess(p) < -margin;
  };
  const std::int64_t nt = static_cast<std::int64_t>(tri.size());
  std::vector<Vec2> cc(tri.size());
  std::vector<std::uint8_t> cc_inside(tri.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t t = 0; t < nt; ++t) {
    const Point c = CGAL::circumcenter(tri[t]->vertex(0)->point(), tri[t]->vertex(1)->point(),
                                       tri[t]->vertex(2)->point());
    cc[t] = Vec2(c.x(), c.y());
    cc_inside[t] = inside(cc[t]);
  }
  // One Voronoi vertex per group of adjacent triangles with (nearly) equal
  // circumcentres; the group's id is its lowest triangle.
  const double weld = kWeldTolerance * domain.scale;
  std::vector<Index> group(tri.size());
  for (std::size_t t = 0; t < tri.size(); ++t) group[t] = static_cast<Index>(t);
  auto root = [&](Index t) {
    while (group[t] != t) t = group[t] = group[group[t]];
    return t;
  };
  for (std::size_t t = 0; t < tri.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index u = tri[t]->neighbor(k)->info();
      if (u == kInvalidIndex || u < t || (cc[t] - cc[u]).squaredNorm() > weld * weld) continue;
      const Index a = root(static_cast<Index>(t)), b = root(u);
      group[std::max(a, b)] = std::min(a, b);
    }
  for (std::size_t t = 0; t < tri.size(); ++t) group[t] = root(static_cast<Index>(t));

  const double on = kOnTolerance * domain.scale;
  const std::vector<Vec2> start =
      domain.is_rectangle ? domain.corners
                          : std::vector<Vec2>{domain.lo, {domain.hi.x(), domain.lo.y()}, domain.hi,
                                              {domain.lo.x(), domain.hi.y()}};
  const bool complex = output == CellOutput::Complex;
  ClippedCells2 out;
  out.centroids.resize(n);
  // Interior cells' loops of triangle groups go to per-thread flat buffers
  // (no allocation per cell): cell i is buffer loop_buf[i] from loop_at[i],
  // loop_len[i] long. Boundary cells keep their clipped polygon.
  const int nthreads = omp_get_max_threads();
  std::vector<std::vector<Index>> buffers(complex ? nthreads : 0);
  std::vector<std::uint32_t> loop_buf(complex ? n : 0), loop_at(complex ? n : 0), loop_len(complex ? n : 0);
  std::vector<std::vector<Vec2>> clipped(complex ? n : 0);  // boundary cells: clipped polygon
  std::vector<std::uint8_t> vanished(n, 0);
  std::vector<Index> duplicate(n, kInvalidIndex);  // a neighbour closer than duplicate_distance
  const double d2 = std::pow(duplicate_tolerance * domain.scale, 2);
  const std::int64_t ns = static_cast<std::int64_t>(n);
#pragma omp parallel
  {
    std::vector<Vec2> poly, scratch;
    std::vector<double> side;
    std::vector<Index> loop;
    const int me = omp_get_thread_num();
    if (complex) buffers[me].reserve(7 * n / nthreads + 1024);
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t q = 0; q < ns; ++q) {
      const Index i = order[q];
      const Vec2 s(seeds[i].x(), seeds[i].y());
      bool interior = true;
      loop.clear();
      auto fc = dt.incident_faces(handle[i]), done = fc;
      do {
        const Index t = fc->info();
        if (t == kInvalidIndex || !cc_inside[t]) {
          interior = false;
          break;
        }
        const auto nb = fc->vertex(Delaunay::ccw(fc->index(handle[i])));
        if ((seeds[nb->info()] - seeds[i]).squaredNorm() < d2) duplicate[i] = nb->info();
        if (loop.empty() || loop.back() != group[t]) loop.push_back(group[t]);
      } while (++fc != done);
      while (interior && loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
      if (interior && loop.size() >= 3) {
        poly.clear();
        for (Index g : loop) poly.push_back(cc[g]);
        const Vec2 c = polygonCentroid(poly);
        out.centroids[i] = Vec3(c.x(), c.y(), 0);
        if (complex) {
          std::vector<Index>& buf = buffers[me];
          loop_buf[i] = static_cast<std::uint32_t>(me);
          loop_at[i] = static_cast<std::uint32_t>(buf.size());
          loop_len[i] = static_cast<std::uint32_t>(loop.size());
          buf.insert(buf.end(), loop.begin(), loop.end());
        }
        continue;
      }
      poly = start;
      auto circ = dt.incident_vertices(handle[i]), vdone = circ;
      do {
        if (dt.is_infinite(circ)) continue;
        if ((seeds[circ->info()] - seeds[i]).squaredNorm() < d2) duplicate[i] = circ->info();
        const Vec2 t(circ->point().x(), circ->point().y());
        const Vec2 d = t - s;
        const Vec2 normal = d / d.norm();
        clipPolygon(poly, scratch, side, normal, normal.dot((s + t) / 2), on);
      } while (++circ != vdone);
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
      if (poly.size() < 3) {
        vanished[i] = 1;
        continue;
      }
      const Vec2 c = polygonCentroid(poly);
      out.centroids[i] = Vec3(c.x(), c.y(), 0);
      if (complex) clipped[i] = poly;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (duplicate[i] != kInvalidIndex) throwDuplicate(seeds, i, duplicate[i]);
  for (std::size_t i = 0; i < n; ++i)
    if (vanished[i])
      throw GeometryError("the Voronoi cell of " + describeSeed(i, seeds[i]) +
                          " vanished when clipped to the domain");
  if (!complex) return out;

  // Vertex keys: a triangle group (< nt), or nt + k for the k-th point made
  // by clipping. Clipped points weld onto the circumcentres of the boundary
  // cells' triangles first (entered before any of them), then onto each other.
  VertexWelder welder(Vec3(domain.lo.x(), domain.lo.y(), 0), weld, 0);
  std::vector<Index> key_of_weld;
  std::vector<Vec3> extra;
  std::vector<Index> boundary;  // boundary cells in seed order
  for (std::size_t i = 0; i < n; ++i)
    if (!clipped[i].empty()) boundary.push_back(static_cast<Index>(i));
  for (Index i : boundary) {
    auto fc = dt.incident_faces(handle[i]), done = fc;
    do {
      const Index t = fc->info();
      // A circumcentre on the boundary (to the weld tolerance) is left to the
      // clipped points, which lie exactly on it.
      if (t == kInvalidIndex || domain.excess(cc[t]) > -2 * weld) continue;
      const Index w = welder.weld(Vec3(cc[t].x(), cc[t].y(), 0));
      if (w == key_of_weld.size()) key_of_weld.push_back(group[t]);
    } while (++fc != done);
  }
  std::vector<Index> boundary_keys;  // boundary cell b's loop from boundary_at[b]
  std::vector<std::uint32_t> boundary_at(boundary.size() + 1, 0);
  for (std::size_t b = 0; b < boundary.size(); ++b) {
    const Index i = boundary[b];
    const std::size_t first = boundary_keys.size();
    for (const Vec2& p : clipped[i]) {
      const Index w = welder.weld(Vec3(p.x(), p.y(), 0));
      if (w == key_of_weld.size()) {
        key_of_weld.push_back(static_cast<Index>(nt + extra.size()));
        extra.push_back(Vec3(p.x(), p.y(), 0));
      }
      const Index k = key_of_weld[w];
      if (boundary_keys.size() == first || boundary_keys.back() != k) boundary_keys.push_back(k);
    }
    while (boundary_keys.size() > first + 1 && boundary_keys.back() == boundary_keys[first])
      boundary_keys.pop_back();
    if (boundary_keys.size() - first < 3)
      throw GeometryError("the Voronoi cell of " + describeSeed(i, seeds[i]) +
                          " collapsed to fewer than 3 vertices when its vertices were welded");
    boundary_at[b + 1] = static_cast<std::uint32_t>(boundary_keys.size());
    loop_buf[i] = static_cast<std::uint32_t>(nthreads);  // the boundary buffer
    loop_at[i] = boundary_at[b];
    loop_len[i] = boundary_at[b + 1] - boundary_at[b];
  }
  // Vertices numbered in key order: triangles in CGAL's storage order (along
  // its spatial sort), then the clipped points. Neighbouring vertices get
  // nearby numbers whatever the seeds' order, which keeps building the complex
  // cache-friendly; the numbering does not depend on the thread count.
  std::vector<Index> id(tri.size() + extra.size(), kInvalidIndex);
  for (const auto& buf : buffers)
    for (Index k : buf) id[k] = 0;
  for (Index k : boundary_keys) id[k] = 0;
  out.positions.reserve(2 * n + extra.size());
  for (std::size_t k = 0; k < id.size(); ++k)
    if (id[k] == 0) {
      id[k] = static_cast<Index>(out.positions.size());
      out.positions.push_back(k < tri.size() ? Vec3(cc[k].x(), cc[k].y(), 0) : extra[k - tri.size()]);
    }
  for (auto& buf : buffers)
    for (Index& k : buf) k = id[k];
  for (Index& k : boundary_keys) k = id[k];
  buffers.push_back(std::move(boundary_keys));
  // Cell k = seed k.
  out.offsets.resize(n + 1);
  out.offsets[0] = 0;
  for (std::size_t i = 0; i < n; ++i) out.offsets[i + 1] = out.offsets[i] + loop_len[i];
  out.loops.resize(out.offsets[n]);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < ns; ++i) {
    const Index* src = buffers[loop_buf[i]].data() + loop_at[i];
    std::copy(src, src + loop_len[i], out.loops.begin() + out.offsets[i]);
  }
  out.order = std::move(order);
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
  return buildPolygonTissue(std::move(cells.positions), cells.offsets, cells.loops, Embedding::Planar,
                            cells.order);
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
