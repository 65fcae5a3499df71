// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 2D Voronoi tissues from CGAL's Delaunay triangulation. Voronoi vertices are
// the circumcentres of Delaunay triangles (triangles whose circumcentres lie
// within the weld tolerance, e.g. 4 cocircular seeds, are one vertex). A cell
// whose triangles' circumcentres all lie inside the domain is read off its
// triangles directly; only the cells reaching the boundary are clipped (the
// domain cut by the bisector of every Delaunay neighbour) and their vertices
// welded onto those circumcentres, so walls are exactly the dual of Delaunay
// edges. Per-cell work runs in parallel; numbering is sequential, so the
// result does not depend on the thread count.
//
// With many seeds the triangulation, the one serial step left, is split: the
// left and right halves (at the median x) are triangulated side by side, each
// with the other's seeds within a margin, and every cell is read from its own
// half. A cell is kept only if it is certainly exact (no vertex of it closer
// to a seed its half left out than to its own seed); otherwise the whole job
// falls back to one triangulation, so the split changes speed, never the
// result's correctness.

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
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

#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "voronoi_cells.hpp"
#include "spatial_order.hpp"
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

// Whether the boundary welding takes a circumcentre as a vertex: clearly
// inside the domain (one within 2x the weld tolerance of the boundary is left
// to the clipped points, which lie exactly on it).
bool weldedAsCircumcentre(const ConvexDomain2& domain, const Vec2& p) {
  return domain.excess(p) <= -2 * kWeldTolerance * domain.scale;
}

// Inserts the seeds in `insertion` order (see spatialOrder2), each from the
// face of the seed inserted before: the walk to its place stays short.
void insertSeeds(Delaunay& dt, std::span<const Vec3> seeds, std::span<const Index> insertion) {
  Delaunay::Face_handle hint;
  for (Index i : insertion) {
    const std::size_t before = dt.number_of_vertices();
    const Delaunay::Vertex_handle v = dt.insert(Point(seeds[i].x(), seeds[i].y()), hint);
    if (dt.number_of_vertices() == before) throwDuplicate(seeds, i, v->info());  // an exact duplicate
    v->info() = i;
    hint = v->face();
  }
}

[[noreturn]] void throwCollinear(std::span<const Vec3> seeds) {
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

// The Delaunay triangulation(s) the cells are read from: one of all seeds,
// or (split) one per half of the domain, built in parallel, each seed's cell
// read from its owner's. Triangles have global ids (face->info(); a triangle
// two halves share has one id); seeds closer than duplicate_distance are found
// among Delaunay neighbours (the nearest neighbour of every seed is one) when
// the cells are read.
struct Triangulation2 {
  std::vector<std::unique_ptr<Delaunay>> dts;
  std::vector<std::uint8_t> owner;              // per seed: its triangulation
  std::vector<Delaunay::Vertex_handle> handle;  // per seed, in its owner
  std::vector<Delaunay::Face_handle> tri;       // by global id
  // Split: each half left out the seeds beyond split + margin (left half) or
  // below split - margin (right half). A cell read from a half is exact when
  // each of its vertices is closer to its seed than to any left-out seed.
  double split = 0, margin = 0;

  bool exact(std::uint8_t side, const Vec2& seed, const Vec2& p) const {
    if (dts.size() == 1) return true;
    const double r = (p - seed).norm();
    return side == 0 ? p.x() + r < split + margin : p.x() - r > split - margin;
  }
};

Triangulation2 triangulateWhole(std::span<const Vec3> seeds, std::span<const Index> insertion) {
  Triangulation2 tr;
  tr.dts.push_back(std::make_unique<Delaunay>());
  Delaunay& dt = *tr.dts[0];
  insertSeeds(dt, seeds, insertion);
  if (dt.dimension() < 2) throwCollinear(seeds);
  tr.owner.assign(seeds.size(), 0);
  tr.handle.resize(seeds.size());
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) tr.handle[v->info()] = v;
  // Finite triangles numbered in CGAL's (deterministic) storage order.
  tr.tri.reserve(2 * seeds.size());
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) {
    if (dt.is_infinite(f)) {
      f->info() = kInvalidIndex;
      continue;
    }
    f->info() = static_cast<Index>(tr.tri.size());
    tr.tri.push_back(f);
  }
  return tr;
}

// Seeds per mean spacing of margin each half keeps beyond the split line:
// a cell of uniformly spread seeds is wider than this with negligible
// probability; a wider one sends the whole job to triangulateWhole.
constexpr double kSplitMargin = 8.0;
// Below this many seeds one triangulation is fast enough.
constexpr std::size_t kSplitMinSeeds = 100000;

// The split triangulation, or nothing when the seeds do not lend themselves
// to it (a half degenerate, a shared triangle triangulated differently by the
// two halves, e.g. cocircular seeds on the split line).
std::optional<Triangulation2> triangulateSplit(std::span<const Vec3> seeds, std::span<const Index> insertion,
                                               const ConvexDomain2& domain) {
  const std::size_t n = seeds.size();
  Triangulation2 tr;
  std::vector<double> xs(n);
  double lo_x = seeds[0].x(), hi_x = lo_x, lo_y = seeds[0].y(), hi_y = lo_y;
  for (std::size_t i = 0; i < n; ++i) {
    xs[i] = seeds[i].x();
    lo_x = std::min(lo_x, seeds[i].x());
    hi_x = std::max(hi_x, seeds[i].x());
    lo_y = std::min(lo_y, seeds[i].y());
    hi_y = std::max(hi_y, seeds[i].y());
  }
  std::nth_element(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(n / 2), xs.end());
  tr.split = xs[n / 2];
  tr.margin = kSplitMargin * std::sqrt((hi_x - lo_x) * (hi_y - lo_y) / static_cast<double>(n));
  if (!(tr.margin > 0) || tr.split - tr.margin <= lo_x || tr.split + tr.margin >= hi_x) return std::nullopt;
  std::array<std::vector<Index>, 2> side_insertion;
  tr.owner.resize(n);
  for (Index i : insertion) {
    const double x = seeds[i].x();
    if (x <= tr.split + tr.margin) side_insertion[0].push_back(i);
    if (x >= tr.split - tr.margin) side_insertion[1].push_back(i);
    tr.owner[i] = x <= tr.split ? 0 : 1;
  }
  tr.dts.push_back(std::make_unique<Delaunay>());
  tr.dts.push_back(std::make_unique<Delaunay>());
  tr.handle.resize(n);
  // Each half, in its own thread, triangulates its seeds, takes the handles
  // of the seeds it owns and lists the triangles it numbers: those with a
  // corner it owns, except (right half) those with corners owned by both,
  // which the left half numbers and the right half looks up by their corners.
  std::array<std::vector<Delaunay::Face_handle>, 2> numbered, border;
  std::array<std::exception_ptr, 2> failed;
#pragma omp parallel for num_threads(2) schedule(static, 1)
  for (int s = 0; s < 2; ++s) {
    try {
      Delaunay& dt = *tr.dts[s];
      insertSeeds(dt, seeds, side_insertion[s]);
      if (dt.dimension() < 2) continue;
      for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
        if (tr.owner[v->info()] == s) tr.handle[v->info()] = v;
      for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) {
        f->info() = kInvalidIndex;
        if (dt.is_infinite(f)) continue;
        int mine = 0;
        for (int k = 0; k < 3; ++k) mine += tr.owner[f->vertex(k)->info()] == s;
        if (mine == 0) continue;  // only a neighbour's triangle: never read from here
        if (mine < 3) border[s].push_back(f);
        if (mine < 3 && s == 1) continue;
        f->info() = static_cast<Index>(numbered[s].size());
        numbered[s].push_back(f);
      }
    } catch (...) {
      failed[s] = std::current_exception();
    }
  }
  for (const auto& e : failed)  // a duplicate is an error whichever half found it
    if (e) std::rethrow_exception(e);
  for (const auto& dt : tr.dts)
    if (dt->dimension() < 2) return std::nullopt;
  const Index left = static_cast<Index>(numbered[0].size());
  const std::int64_t right = static_cast<std::int64_t>(numbered[1].size());
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < right; ++k) numbered[1][k]->info() += left;
  tr.tri = std::move(numbered[0]);
  tr.tri.insert(tr.tri.end(), numbered[1].begin(), numbered[1].end());
  using Corners = std::array<Index, 3>;
  auto corners = [](Delaunay::Face_handle f) {
    Corners c = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::sort(c.begin(), c.end());
    return c;
  };
  struct CornersHash {
    std::size_t operator()(const Corners& c) const {
      return std::hash<std::uint64_t>()((std::uint64_t(c[0]) << 32) ^ (std::uint64_t(c[1]) << 16) ^ c[2]);
    }
  };
  std::unordered_map<Corners, Index, CornersHash> shared;
  for (Delaunay::Face_handle f : border[0]) shared.emplace(corners(f), f->info());
  for (Delaunay::Face_handle f : border[1]) {
    const auto it = shared.find(corners(f));
    if (it != shared.end()) {
      f->info() = it->second;
      continue;
    }
    // Not in the left half: harmless for a triangle whose circumcentre is
    // outside the domain (e.g. a sliver along the hull of the right half's
    // seeds), whose cells are clipped by their neighbours' bisectors and
    // certified from the clipped polygon; otherwise, e.g. cocircular seeds
    // triangulated two ways, the split is given up.
    const Point cc = CGAL::circumcenter(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    if (weldedAsCircumcentre(domain, Vec2(cc.x(), cc.y()))) return std::nullopt;
  }
  return tr;
}

// --- clipCells, phase 1: the dual arrays ---------------------------------------

// The Voronoi vertices before welding: one circumcentre per finite triangle
// (by global triangle id), whether it lies inside the domain by the interior
// margin, and its weld group: adjacent triangles with (nearly) equal
// circumcentres are one vertex, named by the group's lowest triangle.
struct DualVertices2 {
  std::vector<Vec2> cc;
  std::vector<std::uint8_t> inside;
  std::vector<Index> group;
};

// A cell is interior when all its triangles are finite and their circumcentres
// lie inside the domain by a margin far above the clipping tolerances.
void computeCircumcentres(const Triangulation2& tr, const ConvexDomain2& domain, DualVertices2& dual) {
  const auto& tri = tr.tri;
  const double margin = kInteriorMargin * domain.scale;
  auto inside = [&](const Vec2& p) {
    if (domain.is_rectangle)
      return p.x() > domain.lo.x() + margin && p.x() < domain.hi.x() - margin &&
             p.y() > domain.lo.y() + margin && p.y() < domain.hi.y() - margin;
    if ((p - domain.center).norm() < domain.inner_radius - margin) return true;
    return domain.excess(p) < -margin;
  };
  const std::int64_t nt = static_cast<std::int64_t>(tri.size());
  dual.cc.resize(tri.size());
  dual.inside.resize(tri.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t t = 0; t < nt; ++t) {
    const Point c = CGAL::circumcenter(tri[t]->vertex(0)->point(), tri[t]->vertex(1)->point(),
                                       tri[t]->vertex(2)->point());
    dual.cc[t] = Vec2(c.x(), c.y());
    dual.inside[t] = inside(dual.cc[t]);
  }
}

void groupCloseCircumcentres(const Triangulation2& tr, double weld, DualVertices2& dual) {
  const auto& tri = tr.tri;
  const auto& cc = dual.cc;
  std::vector<Index>& group = dual.group;
  group.resize(tri.size());
  for (std::size_t t = 0; t < tri.size(); ++t) group[t] = static_cast<Index>(t);
  auto root = [&](Index t) {
    while (group[t] != t) t = group[t] = group[group[t]];
    return t;
  };
  // Such neighbours are rare (cocircular seeds): find them in parallel, join serially.
  const std::int64_t nt = static_cast<std::int64_t>(tri.size());
  std::vector<std::vector<std::pair<Index, Index>>> close(omp_get_max_threads());
#pragma omp parallel
  {
    auto& mine = close[omp_get_thread_num()];
#pragma omp for schedule(static)
    for (std::int64_t t = 0; t < nt; ++t)
      for (int k = 0; k < 3; ++k) {
        const Index u = tri[t]->neighbor(k)->info();
        if (u != kInvalidIndex && u > t && (cc[t] - cc[u]).squaredNorm() <= weld * weld)
          mine.emplace_back(static_cast<Index>(t), u);
      }
  }
  for (const auto& pairs : close)  // in any order: the groups and their lowest ids are the same
    for (const auto& [t, u] : pairs) {
      const Index a = root(t), b = root(u);
      group[std::max(a, b)] = std::min(a, b);
    }
  for (const auto& pairs : close)
    for (const auto& [t, u] : pairs) group[t] = root(t), group[u] = root(u);
}

DualVertices2 dualVertices(const Triangulation2& tr, const ConvexDomain2& domain) {
  DualVertices2 dual;
  computeCircumcentres(tr, domain, dual);
  groupCloseCircumcentres(tr, kWeldTolerance * domain.scale, dual);
  return dual;
}

// --- clipCells, phase 2: reading (interior) or clipping (boundary) each cell ----

// What reading the cells found. Interior cells' loops of weld groups go to
// per-thread flat buffers (no allocation per cell): cell i is buffers[buf[i]]
// from at[i], len[i] long. Boundary cells keep their clipped polygon.
struct CellLoops2 {
  std::vector<std::vector<Index>> buffers;
  std::vector<std::uint32_t> buf, at, len;
  std::vector<std::vector<Vec2>> clipped;
  std::vector<std::uint8_t> vanished, inexact;
  std::vector<Index> duplicate;  // a neighbour closer than the duplicate distance
};

// One cell at a time, from any thread: each writes only its own cell's slots.
struct CellReader2 {
  const ConvexDomain2& domain;
  const Triangulation2& tr;
  const DualVertices2& dual;
  bool complex;
  double d2;  // squared duplicate distance
  double on;  // clipping tolerance
  std::vector<Vec2> start;  // the polygon every boundary cell is clipped from
  CellLoops2& loops;
  ClippedCells2& out;

  struct Scratch {
    std::vector<Vec2> poly, scratch;
    std::vector<double> side;
    std::vector<Index> loop;
  };

  // The cell's loop of weld groups if it is interior (true); false for a
  // boundary cell, left to clip().
  bool readInterior(Index i, int thread, Scratch& s) const {
    const std::uint8_t half = tr.owner[i];
    const Delaunay& dt = *tr.dts[half];
    // Seed positions come from the triangulation's vertices (already in
    // cache), not from the seeds, whose order is the user's.
    const Point& pi = tr.handle[i]->point();
    const Vec2 seed(pi.x(), pi.y());
    bool interior = true, exact_loop = true;
    s.loop.clear();
    auto fc = dt.incident_faces(tr.handle[i]), done = fc;
    do {
      const Index t = fc->info();
      if (t == kInvalidIndex || !dual.inside[t]) {
        interior = false;
        break;
      }
      const auto nb = fc->vertex(Delaunay::ccw(fc->index(tr.handle[i])));
      if (CGAL::squared_distance(nb->point(), pi) < d2) loops.duplicate[i] = nb->info();
      exact_loop &= tr.exact(half, seed, dual.cc[t]);
      if (s.loop.empty() || s.loop.back() != dual.group[t]) s.loop.push_back(dual.group[t]);
    } while (++fc != done);
    while (interior && s.loop.size() > 1 && s.loop.back() == s.loop.front()) s.loop.pop_back();
    if (!interior || s.loop.size() < 3) return false;
    loops.inexact[i] = !exact_loop;
    if (complex) {
      std::vector<Index>& buf = loops.buffers[thread];
      loops.buf[i] = static_cast<std::uint32_t>(thread);
      loops.at[i] = static_cast<std::uint32_t>(buf.size());
      loops.len[i] = static_cast<std::uint32_t>(s.loop.size());
      buf.insert(buf.end(), s.loop.begin(), s.loop.end());
    } else {
      s.poly.clear();
      for (Index g : s.loop) s.poly.push_back(dual.cc[g]);
      const Vec2 c = polygonCentroid(s.poly);
      out.centroids[i] = Vec3(c.x(), c.y(), 0);
    }
    return true;
  }

  // A boundary cell: the domain cut by the bisector of every Delaunay neighbour.
  void clip(Index i, Scratch& s) const {
    const std::uint8_t half = tr.owner[i];
    const Delaunay& dt = *tr.dts[half];
    const Point& pi = tr.handle[i]->point();
    const Vec2 seed(pi.x(), pi.y());
    s.poly = start;
    auto circ = dt.incident_vertices(tr.handle[i]), vdone = circ;
    do {
      if (dt.is_infinite(circ)) continue;
      if (CGAL::squared_distance(circ->point(), pi) < d2) loops.duplicate[i] = circ->info();
      const Vec2 t(circ->point().x(), circ->point().y());
      const Vec2 d = t - seed;
      const Vec2 normal = d / d.norm();
      clipPolygon(s.poly, s.scratch, s.side, normal, normal.dot((seed + t) / 2), on);
    } while (++circ != vdone);
    if (!domain.is_rectangle) {
      // Only cells reaching past the polygon's inscribed circle meet its sides.
      double reach = 0;
      for (const Vec2& p : s.poly) reach = std::max(reach, (p - seed).norm());
      if ((seed - domain.center).norm() + reach >= domain.inner_radius) {
        for (const HalfPlane& hp : domain.sides)
          if (hp.offset - hp.normal.dot(seed) < reach + on)
            clipPolygon(s.poly, s.scratch, s.side, hp.normal, hp.offset, on);
      }
    }
    if (s.poly.size() < 3) {
      loops.vanished[i] = 1;
      return;
    }
    if (tr.dts.size() > 1) {
      for (const Vec2& p : s.poly) loops.inexact[i] |= !tr.exact(half, seed, p);
      auto face = dt.incident_faces(tr.handle[i]), first = face;
      do {  // circumcentres the boundary welding uses (weldBoundaryCells)
        const Index t = face->info();
        if (t != kInvalidIndex && weldedAsCircumcentre(domain, dual.cc[t]))
          loops.inexact[i] |= !tr.exact(half, seed, dual.cc[t]);
      } while (++face != first);
    }
    if (complex) {
      loops.clipped[i] = s.poly;
    } else {
      const Vec2 c = polygonCentroid(s.poly);
      out.centroids[i] = Vec3(c.x(), c.y(), 0);
    }
  }
};

CellLoops2 readCells(std::size_t n, const ConvexDomain2& domain, double duplicate_tolerance, bool complex,
                     const Triangulation2& tr, const DualVertices2& dual, std::span<const Index> order,
                     ClippedCells2& out) {
  const int nthreads = omp_get_max_threads();
  CellLoops2 loops;
  loops.buffers.resize(complex ? nthreads : 0);
  loops.buf.resize(complex ? n : 0);
  loops.at.resize(complex ? n : 0);
  loops.len.resize(complex ? n : 0);
  loops.clipped.resize(complex ? n : 0);
  loops.vanished.assign(n, 0);
  loops.inexact.assign(n, 0);
  loops.duplicate.assign(n, kInvalidIndex);
  const CellReader2 reader{
      domain, tr, dual, complex, std::pow(duplicate_tolerance * domain.scale, 2), kOnTolerance * domain.scale,
      domain.is_rectangle ? domain.corners
                          : std::vector<Vec2>{domain.lo, {domain.hi.x(), domain.lo.y()}, domain.hi,
                                              {domain.lo.x(), domain.hi.y()}},
      loops, out};
  const std::int64_t ns = static_cast<std::int64_t>(n);
#pragma omp parallel
  {
    CellReader2::Scratch scratch;
    const int me = omp_get_thread_num();
    if (complex) loops.buffers[me].reserve(7 * n / nthreads + 1024);
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t q = 0; q < ns; ++q) {
      const Index i = order[q];
      if (!reader.readInterior(i, me, scratch)) reader.clip(i, scratch);
    }
  }
  return loops;
}

// Duplicate seeds and vanished cells are errors; false when a cell read from
// a half of a split triangulation is not certainly exact.
bool certified(std::span<const Vec3> seeds, const CellLoops2& loops) {
  const std::size_t n = seeds.size();
  for (std::size_t i = 0; i < n; ++i)
    if (loops.duplicate[i] != kInvalidIndex) throwDuplicate(seeds, i, loops.duplicate[i]);
  if (std::find(loops.inexact.begin(), loops.inexact.end(), 1) != loops.inexact.end()) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (loops.vanished[i])
      throw GeometryError("the Voronoi cell of " + describeSeed(i, seeds[i]) + " vanished when clipped to the domain");
  return true;
}

// --- clipCells, phase 3: welding the boundary cells' vertices --------------------

// Vertex keys: a triangle group (< nt), or nt + k for the k-th point made by
// clipping. Clipped points weld onto the circumcentres of the boundary cells'
// triangles first (entered before any of them), then onto each other. Each
// boundary cell's loop of keys goes to one more buffer; returns the points
// made by clipping.
std::vector<Vec3> weldBoundaryCells(std::span<const Vec3> seeds, const ConvexDomain2& domain,
                                    const Triangulation2& tr, const DualVertices2& dual, CellLoops2& loops) {
  const std::size_t n = seeds.size(), nt = dual.cc.size();
  VertexWelder welder(Vec3(domain.lo.x(), domain.lo.y(), 0), kWeldTolerance * domain.scale, 0);
  std::vector<Index> key_of_weld;
  std::vector<Vec3> extra;
  std::vector<Index> boundary;  // boundary cells in seed order
  for (std::size_t i = 0; i < n; ++i)
    if (!loops.clipped[i].empty()) boundary.push_back(static_cast<Index>(i));
  for (Index i : boundary) {
    auto fc = tr.dts[tr.owner[i]]->incident_faces(tr.handle[i]), done = fc;
    do {
      const Index t = fc->info();
      if (t == kInvalidIndex || !weldedAsCircumcentre(domain, dual.cc[t])) continue;
      const Index w = welder.weld(Vec3(dual.cc[t].x(), dual.cc[t].y(), 0));
      if (w == key_of_weld.size()) key_of_weld.push_back(dual.group[t]);
    } while (++fc != done);
  }
  const auto boundary_buffer = static_cast<std::uint32_t>(loops.buffers.size());
  std::vector<Index> keys;  // boundary cell b's loop from starts[b]
  std::vector<std::uint32_t> starts(boundary.size() + 1, 0);
  for (std::size_t b = 0; b < boundary.size(); ++b) {
    const Index i = boundary[b];
    const std::size_t first = keys.size();
    for (const Vec2& p : loops.clipped[i]) {
      const Index w = welder.weld(Vec3(p.x(), p.y(), 0));
      if (w == key_of_weld.size()) {
        key_of_weld.push_back(static_cast<Index>(nt + extra.size()));
        extra.push_back(Vec3(p.x(), p.y(), 0));
      }
      const Index k = key_of_weld[w];
      if (keys.size() == first || keys.back() != k) keys.push_back(k);
    }
    while (keys.size() > first + 1 && keys.back() == keys[first]) keys.pop_back();
    if (keys.size() - first < 3)
      throw GeometryError("the Voronoi cell of " + describeSeed(i, seeds[i]) +
                          " collapsed to fewer than 3 vertices when its vertices were welded");
    starts[b + 1] = static_cast<std::uint32_t>(keys.size());
    loops.buf[i] = boundary_buffer;
    loops.at[i] = starts[b];
    loops.len[i] = starts[b + 1] - starts[b];
  }
  loops.buffers.push_back(std::move(keys));
  return extra;
}

// --- clipCells, phase 4: the loops and vertices of the tissue --------------------

// Loops listed in visiting order (loop q is cell order[q]); vertices numbered
// by first use along them: neighbouring vertices get nearby numbers whatever
// the seeds' order, which keeps building the complex cache-friendly; the
// numbering does not depend on the thread count.
void buildLoops(const DualVertices2& dual, const CellLoops2& loops, const std::vector<Vec3>& extra,
                std::span<const Index> order, ClippedCells2& out) {
  const std::size_t n = order.size(), nt = dual.cc.size();
  out.offsets.resize(n + 1);
  out.offsets[0] = 0;
  for (std::size_t q = 0; q < n; ++q) out.offsets[q + 1] = out.offsets[q] + loops.len[order[q]];
  out.loops.resize(out.offsets[n]);
  const std::int64_t ns = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t q = 0; q < ns; ++q) {
    const Index i = order[q];
    const Index* src = loops.buffers[loops.buf[i]].data() + loops.at[i];
    std::copy(src, src + loops.len[i], out.loops.begin() + out.offsets[q]);
  }
  std::vector<Index> id(nt + extra.size(), kInvalidIndex);
  out.positions.reserve(2 * n + extra.size());
  for (Index& k : out.loops) {
    if (id[k] == kInvalidIndex) {
      id[k] = static_cast<Index>(out.positions.size());
      out.positions.push_back(k < nt ? Vec3(dual.cc[k].x(), dual.cc[k].y(), 0) : extra[k - nt]);
    }
    k = id[k];
  }
  out.order.assign(order.begin(), order.end());
}

// The cells of `tr`'s seeds clipped to the domain, or nothing when a cell
// read from a half of a split triangulation is not certainly exact.
std::optional<ClippedCells2> clipCells(std::span<const Vec3> seeds, const ConvexDomain2& domain,
                                       double duplicate_tolerance, CellOutput output, const Triangulation2& tr,
                                       std::span<const Index> order) {
  const DualVertices2 dual = dualVertices(tr, domain);
  const bool complex = output == CellOutput::Complex;
  ClippedCells2 out;
  if (!complex) out.centroids.resize(seeds.size());
  CellLoops2 loops = readCells(seeds.size(), domain, duplicate_tolerance, complex, tr, dual, order, out);
  if (!certified(seeds, loops)) return std::nullopt;
  if (!complex) return out;
  const std::vector<Vec3> extra = weldBoundaryCells(seeds, domain, tr, dual, loops);
  buildLoops(dual, loops, extra, order, out);
  return out;
}

}  // namespace

ClippedCells2 clipVoronoi2(std::span<const Vec3> seeds, const ConvexDomain2& domain,
                           double duplicate_tolerance, CellOutput output) {
  // Seeds are inserted in BRIO order; cells are visited, and their loops
  // listed, along a Hilbert curve: nearby cells one after the other touch
  // nearby memory.
  SpatialOrder2 orders = spatialOrder2(seeds);
  // Many seeds: two halves triangulated side by side (whatever the thread
  // count, so the result does not depend on it), one triangulation if the
  // halves' cells cannot all be certified exact.
  if (seeds.size() >= kSplitMinSeeds) {
    if (std::optional<Triangulation2> tr = triangulateSplit(seeds, orders.insertion, domain))
      if (std::optional<ClippedCells2> cells =
              clipCells(seeds, domain, duplicate_tolerance, output, *tr, orders.hilbert))
        return std::move(*cells);
  }
  const Triangulation2 tr = triangulateWhole(seeds, orders.insertion);
  return *clipCells(seeds, domain, duplicate_tolerance, output, tr, orders.hilbert);
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
