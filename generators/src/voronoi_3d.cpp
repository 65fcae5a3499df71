// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 3D Voronoi tissues from CGAL's Delaunay tetrahedralisation. Voronoi
// vertices are the circumcentres of Delaunay cells (adjacent cells whose
// circumcentres lie within the weld tolerance, e.g. of cospherical seeds, are
// one vertex); the wall between seeds i and j is the loop of circumcentres of
// the cells around the Delaunay edge ij. A seed whose cells' circumcentres all
// lie inside the domain is read off the triangulation; only the seeds reaching
// the boundary are clipped (the domain cut by the bisector plane of every
// Delaunay neighbour) and their vertices welded onto those circumcentres. Each
// wall between two cells is stored once and must come out identical
// (reversed) from both cells, or a GeometryError says which. Everything
// after the triangulation works on seed ranks along CGAL's spatial insertion
// order (see Tetrahedra), for locality; cell k of the result is seed k.
// Per-cell work and most of the assembly run in parallel; welding and vertex
// numbering are sequential, so the result does not depend on the thread count.

#include <algorithm>
#include <array>
#include <span>
#include <cmath>
#include <iterator>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

// CGAL headers trip -Wnull-dereference in GCC 12 optimised builds (in CGAL's
// own code); silence it for them only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#pragma GCC diagnostic pop

#include <Eigen/Dense>
#include <omp.h>

#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "voronoi_cells.hpp"
#include "voronoi_domain.hpp"
#include "voronoi_polytope.hpp"
#include "voronoi_seed_checks.hpp"
#include "voronoi_weld.hpp"

namespace tessella {
namespace detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
using CellBase =
    CGAL::Triangulation_cell_base_with_info_3<Index, Kernel, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using Point = Kernel::Point_3;

// Face labels: >= 0 a neighbour seed; -1 - k domain face k; the ball's
// bounding box faces (always cut away) get kScaffoldLabel.
constexpr int kScaffoldLabel = -1000000000;
int domainLabel(std::size_t face) { return -1 - static_cast<int>(face); }

// CGAL's spatial (Hilbert) order of the seeds, computed as its range
// insertion computes it (so the ranks are those of inserting all seeds at
// once); `points` gets the seeds as CGAL points, by seed index.
std::vector<Index> spatialOrder(std::span<const Vec3> seeds, std::vector<Point>& points) {
  points.clear();
  points.reserve(seeds.size());
  for (const Vec3& s : seeds) points.emplace_back(s.x(), s.y(), s.z());
  std::vector<std::size_t> sorted(seeds.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) sorted[i] = i;
  using Traits = CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::Pointer_property_map<Point>::type>;
  CGAL::spatial_sort(sorted.begin(), sorted.end(), Traits(CGAL::make_property_map(points), Kernel()));
  return std::vector<Index>(sorted.begin(), sorted.end());
}

// Inserts points[i] for i in `which` (spatial order) one by one, each located
// from the last inserted vertex, as CGAL's range insertion does after its
// sort; a vertex's info is its seed (the last one of exact duplicates).
void insertInOrder(Delaunay& dt, const std::vector<Point>& points, std::span<const Index> which) {
  Delaunay::Vertex_handle hint;
  for (Index i : which) {
    hint = dt.insert(points[i], hint);
    if (hint != Delaunay::Vertex_handle()) hint->info() = i;
  }
}

// One triangulation of all seeds; throws on duplicate or coplanar seeds.
void triangulateWhole(Delaunay& dt, std::span<const Vec3> seeds, const std::vector<Point>& points,
                      std::span<const Index> order) {
  insertInOrder(dt, points, order);
  if (dt.number_of_vertices() < seeds.size()) {  // exact duplicates were merged
    std::vector<std::uint8_t> kept(seeds.size(), 0);
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) kept[v->info()] = 1;
    for (std::size_t i = 0; i < seeds.size(); ++i)
      if (!kept[i]) throwDuplicate(seeds, i, dt.nearest_vertex(points[i])->info());
  }
  if (dt.dimension() < 3) {
    throw InputError("all " + std::to_string(seeds.size()) + " seeds are " +
                     (dt.dimension() == 2 ? "coplanar" : "collinear") + " (" +
                     describeSeed(0, seeds[0]) + ", " + describeSeed(1, seeds[1]) + ", " +
                     describeSeed(2, seeds[2]) +
                     ", ...): their Voronoi cells are unbounded slabs, not a tissue");
  }
  // Seeds closer than duplicate_distance are found among Delaunay neighbours
  // (the nearest neighbour of every seed is one) by clipVoronoi3.
}

// The point on the planes of sorted generators (equidistant from them) and
// of sorted domain faces; least squares when more than 3 planes meet. Never
// inlined: the circumcentres of Delaunay cells and the clipped vertices of
// boundary cells go through this one piece of code, so a Voronoi vertex gets
// the same bits from both (a nearly flat Delaunay cell's circumcentre is
// ill-conditioned, and two formulas would disagree by more than the weld
// tolerance).
[[gnu::noinline]] Vec3 planesPoint(std::span<const Index> generators, std::span<const int> faces,
                                   std::span<const Vec3> seeds, const ConvexDomain3& domain) {
  const std::size_t ng = generators.size(), nf = faces.size();
  Eigen::Matrix<double, Eigen::Dynamic, 3, 0, ClipPolytope::kMaxLabels + 1, 3> a(ng - 1 + nf, 3);
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, ClipPolytope::kMaxLabels + 1, 1> b(ng - 1 + nf);
  const Vec3& s0 = seeds[generators[0]];
  for (std::size_t m = 1; m < ng; ++m) {  // equidistant from s0 and s_m
    const Vec3& sm = seeds[generators[m]];
    a.row(m - 1) = (sm - s0).transpose();
    b(m - 1) = (sm - s0).dot((sm + s0) / 2);
  }
  for (std::size_t k = 0; k < nf; ++k) {
    const HalfSpace& f = domain.faces[faces[k]];
    a.row(ng - 1 + k) = f.normal.transpose();
    b(ng - 1 + k) = f.offset;
  }
  if (a.rows() == 3) {
    const Mat3 a3 = a;
    return a3.partialPivLu().solve(Vec3(b));
  }
  return (a.transpose() * a).ldlt().solve(a.transpose() * b);
}

// The position of a cell vertex computed from the planes through it, named
// canonically (generators sorted by seed index -- `seed_of` maps the ranks
// they are given in -- and domain faces) so that every cell sharing
// the vertex gets the same bits -- clipping interpolates along edges, which
// is ill-conditioned where a bisector grazes an edge (nearly cospherical
// seeds), and different cells would disagree by more than the weld
// tolerance. Falls back to the clipped position if the planes do not pin
// down a point near it. (Not inlined: GCC 12 then warns falsely about the
// bounds of the sorts below.)
[[gnu::noinline]] Vec3 canonicalPosition(const Vec3& clipped, Index cell, std::span<const int> labels,
                                         std::span<const Vec3> seeds, std::span<const Index> seed_of,
                                         const ConvexDomain3& domain) {
  std::array<Index, ClipPolytope::kMaxLabels + 1> generators{};
  std::array<int, ClipPolytope::kMaxLabels> faces{};
  std::size_t ng = 0, nf = 0;
  generators[ng++] = cell;
  for (int l : labels) {
    if (l >= 0) generators[ng++] = static_cast<Index>(l);
    else if (l != kScaffoldLabel) faces[nf++] = -1 - l;
  }
  if (ng - 1 + nf < 3) return clipped;
  std::sort(generators.begin(), generators.begin() + ng, [&](Index a, Index b) { return seed_of[a] < seed_of[b]; });
  std::sort(faces.begin(), faces.begin() + nf);
  Vec3 x = planesPoint(std::span<const Index>(generators.data(), ng), std::span<const int>(faces.data(), nf),
                       seeds, domain);
  if (!x.allFinite() || (x - clipped).norm() > 1e-7 * domain.scale) return clipped;
  if (domain.is_box)  // exactly on the box faces it lies on
    for (std::size_t k = 0; k < nf; ++k) {
      const int axis = faces[k] / 2;
      x[axis] = faces[k] % 2 ? domain.hi[axis] : domain.lo[axis];
    }
  return x;
}

// The walls of many cells before numbering, cell after cell (one store per
// thread, no allocation per cell): wall w has a label (neighbour seed or
// domain face) and the vertex keys keys[starts[w] .. starts[w + 1]),
// counter-clockwise seen from outside its cell. A boundary cell's clipped
// vertices wait in `points` until welded (its walls number them locally).
struct WallStore {
  std::vector<int> labels;
  std::vector<Index> starts{0};
  std::vector<Index> keys;
  std::vector<Vec3> points;
  void add(int label, std::vector<Index>& loop) {
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    if (loop.size() < 3) return;  // a wall welded to nothing (cospherical seeds)
    labels.push_back(label);
    keys.insert(keys.end(), loop.begin(), loop.end());
    starts.push_back(static_cast<Index>(keys.size()));
  }
  std::size_t size() const { return labels.size(); }
  // Drops the walls from `walls` on (a cell's walls that are not kept).
  void truncate(std::size_t walls) {
    labels.resize(walls);
    keys.resize(starts[walls]);
    starts.resize(walls + 1);
  }
};

// Where a cell's walls are: `count` walls from wall `first` of store `store`;
// a boundary cell before welding also has points [first_point, +num_points).
struct CellWallsRef {
  Index store = 0, first = 0, count = 0, first_point = 0, num_points = 0;
};

// A cell's walls read through its CellWallsRef.
struct CellWalls {
  std::span<const int> labels;
  const Index* starts = nullptr;  // wall f: keys[starts[f] .. starts[f + 1])
  const Index* keys = nullptr;
  CellWalls(const std::vector<WallStore>& stores, const CellWallsRef& r)
      : labels(stores[r.store].labels.data() + r.first, r.count),
        starts(stores[r.store].starts.data() + r.first),
        keys(stores[r.store].keys.data()) {}
  std::size_t size() const { return labels.size(); }
  std::span<const Index> loop(std::size_t f) const { return {keys + starts[f], starts[f + 1] - starts[f]}; }
};

bool reverseOf(std::span<const Index> a, std::span<const Index> b) {
  const std::size_t m = a.size();
  if (b.size() != m) return false;
  const auto start = std::find(b.begin(), b.end(), a[0]);
  if (start == b.end()) return false;
  const std::size_t s = static_cast<std::size_t>(start - b.begin());
  for (std::size_t k = 0; k < m; ++k)
    if (a[k] != b[(s + m - k) % m]) return false;
  return true;
}

// --- clipVoronoi3, phase 1: the tetrahedralisation as plain arrays --------------

// CGAL's incidence queries mark cells and are not thread-safe, so the cells'
// vertices and neighbours, and each seed's cells, are copied out once. The
// copy is renumbered for locality: seeds by rank along CGAL's spatial
// (Hilbert) insertion order, cells canonically by their vertex ranks (see
// numberCanonically). Random seeds then put neighbouring seeds, their cells
// and circumcentres next to each other in memory, and every pass below
// streams instead of missing the cache at each step. Only the cell list of
// the tissue (cell k = seed k) and the messages go back to seed indices.
struct Tetrahedra {
  std::vector<std::array<Index, 4>> tv, tn;  // vertex ranks (kInvalidIndex: infinite), neighbour cells
  std::vector<std::uint8_t> finite;
  std::vector<Index> inc_start, inc;  // rank q's cells: inc[inc_start[q] .. inc_start[q + 1]), ascending
  std::vector<Index> order;           // rank q is seed order[q]
  std::vector<Index> rank;            // seed k has rank rank[k]
  std::vector<Vec3> seeds;            // by rank
  std::size_t size() const { return tv.size(); }
};

// Each rank's cells, ascending, from tv.
void incidence(Tetrahedra& tets, std::size_t n) {
  const std::size_t nt = tets.size();
  tets.inc_start.assign(n + 1, 0);
  for (std::size_t t = 0; t < nt; ++t)
    for (Index v : tets.tv[t])
      if (v != kInvalidIndex) ++tets.inc_start[v + 1];
  for (std::size_t i = 0; i < n; ++i) tets.inc_start[i + 1] += tets.inc_start[i];
  tets.inc.resize(tets.inc_start[n]);
  std::vector<Index> fill(tets.inc_start.begin(), tets.inc_start.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
    for (Index v : tets.tv[t])
      if (v != kInvalidIndex) tets.inc[fill[v]++] = static_cast<Index>(t);
}

// The cells of a Delaunay triangulation in any numbering: vertex ranks in
// CGAL's slot order (positively oriented), the neighbour opposite each slot.
struct RawTets {
  std::vector<std::array<Index, 4>> tv, tn;
  std::vector<std::uint8_t> finite;
};

RawTets readWhole(const Delaunay& dt, std::span<const Index> rank) {
  std::vector<Delaunay::Cell_handle> tet;
  tet.reserve(7 * dt.number_of_vertices());
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    c->info() = static_cast<Index>(tet.size());
    tet.push_back(c);
  }
  const std::int64_t nts = static_cast<std::int64_t>(tet.size());
  RawTets raw;
  raw.tv.resize(tet.size());
  raw.tn.resize(tet.size());
  raw.finite.resize(tet.size());
  // (Reading handles is thread-safe; only CGAL's incidence queries are not.)
#pragma omp parallel for schedule(static)
  for (std::int64_t t = 0; t < nts; ++t) {
    for (int k = 0; k < 4; ++k) {
      const auto v = tet[t]->vertex(k);
      raw.tv[t][k] = dt.is_infinite(v) ? kInvalidIndex : rank[v->info()];
      raw.tn[t][k] = tet[t]->neighbor(k)->info();
    }
    raw.finite[t] = !dt.is_infinite(tet[t]);
  }
  return raw;
}

std::array<Index, 4> sortedRanks(std::array<Index, 4> v) {
  std::sort(v.begin(), v.end());  // kInvalidIndex (infinite) last
  return v;
}

// Cells numbered canonically: by their sorted vertex ranks, in lexicographic
// order -- a function of the triangulation alone (unique for any seeds: CGAL
// perturbs degenerate ones symbolically), not of CGAL's storage order nor of
// how it was built (one triangulation or two halves). Sorted first by lowest
// rank, a cell comes right after the cells around the ranks before its
// lowest one, so cells around neighbouring seeds are close in memory.
void numberCanonically(const RawTets& raw, std::size_t n, Tetrahedra& tets) {
  const std::size_t nt = raw.tv.size();
  const std::int64_t nts = static_cast<std::int64_t>(nt), ns = static_cast<std::int64_t>(n);
  std::vector<std::array<Index, 4>> key(nt);
#pragma omp parallel for schedule(static)
  for (std::int64_t t = 0; t < nts; ++t) key[t] = sortedRanks(raw.tv[t]);
  std::vector<Index> start(n + 1, 0), old_of(nt), renumber(nt);
  for (std::size_t t = 0; t < nt; ++t) ++start[key[t][0] + 1];
  for (std::size_t q = 0; q < n; ++q) start[q + 1] += start[q];
  {
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < nt; ++t) old_of[fill[key[t][0]]++] = static_cast<Index>(t);
  }
#pragma omp parallel for schedule(dynamic, 1024)
  for (std::int64_t q = 0; q < ns; ++q)
    std::sort(old_of.begin() + start[q], old_of.begin() + start[q + 1],
              [&](Index a, Index b) { return key[a] < key[b]; });
#pragma omp parallel for schedule(static)
  for (std::int64_t u = 0; u < nts; ++u) renumber[old_of[u]] = static_cast<Index>(u);
  tets.tv.resize(nt);
  tets.tn.resize(nt);
  tets.finite.resize(nt);
#pragma omp parallel for schedule(static)
  for (std::int64_t u = 0; u < nts; ++u) {
    const Index t = old_of[u];
    tets.tv[u] = raw.tv[t];
    tets.finite[u] = raw.finite[t];
    for (int k = 0; k < 4; ++k) tets.tn[u][k] = renumber[raw.tn[t][k]];
  }
}

// --- Two half triangulations side by side --------------------------------------

// Mean spacings of seeds each half keeps beyond the split plane (most
// circumballs of uniformly spread seeds' cells are narrower; the seeds a wider
// one holds are inserted when found), and the fewest seeds worth splitting.
constexpr double kSplitMargin3 = 2.0;
constexpr std::size_t kSplitMinSeeds3 = 5000;

// The seeds a half left out, in bins (boxes of about 32 seeds) with their
// bounding boxes: whether a cell of the half is a cell of the whole
// triangulation is decided by the exact in-sphere test against the left-out
// seeds of the bins its circumball (or, for an infinite cell, the open side of
// its hull facet) may reach.
struct LeftOut {
  Vec3 lo = Vec3::Constant(0), hi = Vec3::Constant(0);  // of all
  std::vector<Vec3> box_lo, box_hi;                     // per bin (empty bins dropped)
  std::vector<Index> start;
  std::vector<Point> points;
  std::vector<Index> seed;             // points[k] is seed seed[k]
  std::vector<std::uint8_t> inserted;  // since inserted into the half (no longer left out)

  LeftOut(std::span<const Vec3> seeds, const std::vector<Point>& all, std::span<const Index> which) {
    if (which.empty()) return;
    lo = hi = seeds[which[0]];
    for (Index i : which) {
      lo = lo.cwiseMin(seeds[i]);
      hi = hi.cwiseMax(seeds[i]);
    }
    const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
    const double w = std::cbrt(extent.prod() * 32.0 / static_cast<double>(which.size()));
    std::array<std::size_t, 3> dims{};
    for (int a = 0; a < 3; ++a) dims[a] = std::clamp<std::size_t>(static_cast<std::size_t>(extent[a] / w) + 1, 1, 64);
    auto binOf = [&](const Vec3& p) {
      std::size_t b = 0;
      for (int a = 2; a >= 0; --a) {
        const auto c = static_cast<std::size_t>((p[a] - lo[a]) / extent[a] * static_cast<double>(dims[a]));
        b = b * dims[a] + std::min(c, dims[a] - 1);
      }
      return b;
    };
    const std::size_t nb = dims[0] * dims[1] * dims[2];
    std::vector<Index> count(nb + 1, 0);
    for (Index i : which) ++count[binOf(seeds[i]) + 1];
    for (std::size_t b = 0; b < nb; ++b) count[b + 1] += count[b];
    std::vector<Index> sorted(which.size());
    {
      std::vector<Index> fill(count.begin(), count.end() - 1);
      for (Index i : which) sorted[fill[binOf(seeds[i])]++] = i;
    }
    start.push_back(0);
    for (std::size_t b = 0; b < nb; ++b) {
      if (count[b] == count[b + 1]) continue;
      Vec3 blo = seeds[sorted[count[b]]], bhi = blo;
      for (Index k = count[b]; k < count[b + 1]; ++k) {
        blo = blo.cwiseMin(seeds[sorted[k]]);
        bhi = bhi.cwiseMax(seeds[sorted[k]]);
        points.push_back(all[sorted[k]]);
        seed.push_back(sorted[k]);
      }
      box_lo.push_back(blo);
      box_hi.push_back(bhi);
      start.push_back(static_cast<Index>(points.size()));
    }
    inserted.assign(points.size(), 0);
  }
};

double squaredDistanceToBox(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return (lo - p).cwiseMax(p - hi).cwiseMax(Vec3::Zero()).squaredNorm();
}

Vec3 toVec(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

// Whether cell c of a half's triangulation is a cell of the triangulation of
// all seeds: no left-out seed (not inserted since) in its circumsphere (or
// beyond its hull facet), by CGAL's exact test with the symbolic perturbation
// the whole triangulation uses. Returns such a seed (its place in `out`), or
// kInvalidIndex. Bins are skipped by floating-point bounds widened far beyond their
// rounding: the circumcentre of a nearly flat cell is ill-conditioned (error
// about machine epsilon times L^4 / 6V for longest edge L and volume V), the
// ball is widened by 1e-10 of that; a hull facet's plane by 1e-9 of its
// edges' and the distance's product.
Index conflict(const Delaunay& dt, Delaunay::Cell_handle c, const LeftOut& out) {
  if (out.points.empty()) return kInvalidIndex;
  auto inBin = [&](std::size_t b) {
    for (Index k = out.start[b]; k < out.start[b + 1]; ++k)
      if (!out.inserted[k] && dt.side_of_sphere(c, out.points[k], true) != CGAL::ON_UNBOUNDED_SIDE) return k;
    return kInvalidIndex;
  };
  const std::size_t nb = out.box_lo.size();
  if (!dt.is_infinite(c)) {
    std::array<Vec3, 4> p;
    for (int k = 0; k < 4; ++k) p[k] = toVec(c->vertex(k)->point());
    const Vec3 cc = toVec(CGAL::circumcenter(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                             c->vertex(3)->point()));
    double r2 = 0, l2 = 0;
    for (int k = 0; k < 4; ++k) {
      r2 = std::max(r2, (p[k] - cc).squaredNorm());
      for (int m = k + 1; m < 4; ++m) l2 = std::max(l2, (p[k] - p[m]).squaredNorm());
    }
    const double v6 = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
    const double r = std::sqrt(r2) + 1e-10 * l2 * l2 / v6;
    if (!std::isfinite(r) || !cc.allFinite()) {
      for (std::size_t b = 0; b < nb; ++b)
        if (const Index k = inBin(b); k != kInvalidIndex) return k;
      return kInvalidIndex;
    }
    if (squaredDistanceToBox(cc, out.lo, out.hi) > r * r) return kInvalidIndex;
    for (std::size_t b = 0; b < nb; ++b)
      if (squaredDistanceToBox(cc, out.box_lo[b], out.box_hi[b]) <= r * r)
        if (const Index k = inBin(b); k != kInvalidIndex) return k;
    return kInvalidIndex;
  }
  const int i = c->index(dt.infinite_vertex());
  std::array<Vec3, 3> f;
  for (int k = 1; k <= 3; ++k) f[k - 1] = toVec(c->vertex((i + k) % 4)->point());
  Vec3 normal = (f[1] - f[0]).cross(f[2] - f[0]);  // towards the open side
  if (normal.dot(toVec(dt.mirror_vertex(c, i)->point()) - f[0]) > 0) normal = -normal;
  const double l = std::max({(f[1] - f[0]).norm(), (f[2] - f[1]).norm(), (f[0] - f[2]).norm()});
  for (std::size_t b = 0; b < nb; ++b) {
    const Vec3 centre = (out.box_lo[b] + out.box_hi[b]) / 2, half = (out.box_hi[b] - out.box_lo[b]) / 2;
    const double reach = normal.dot(centre - f[0]) + normal.cwiseAbs().dot(half);
    const double tol = 1e-9 * l * l * ((centre - f[0]).norm() + half.norm());
    if (reach < -tol) continue;
    if (const Index k = inBin(b); k != kInvalidIndex) return k;
  }
  return kInvalidIndex;
}

// One half's triangulation and the cells it contributes: those whose lowest
// rank it owns. Every cell around a seed it owns is certified (a cell of the
// whole triangulation), so its star is the whole triangulation's and it
// contributes every cell whose lowest rank it owns. A neighbour across a
// facet the half does not contribute is the other half's cell listed with
// that facet (one with a neighbour it does not contribute there).
struct Half {
  std::unique_ptr<Delaunay> dt;
  std::vector<std::array<Index, 4>> tv, tn;  // tn: local cell, or kInvalidIndex (looked up)
  std::vector<std::uint8_t> finite;
  std::vector<std::pair<std::array<Index, 3>, Index>> border;  // (facet's sorted ranks, local cell), sorted
  struct Pending {
    Index cell;
    int slot;
    std::array<Index, 3> key;  // the facet opposite the slot
  };
  std::vector<Pending> pending;
  bool ok = false;
};

void buildHalf(int s, const std::vector<Point>& points, std::span<const Index> kept, LeftOut& out,
               std::span<const Index> rank, std::span<const std::uint8_t> owner_of_rank,
               std::span<const std::uint8_t> owner_of_seed, Half& h) {
  h.dt = std::make_unique<Delaunay>();
  Delaunay& dt = *h.dt;
  insertInOrder(dt, points, kept);
  if (dt.number_of_vertices() != kept.size() || dt.dimension() < 3) return;  // left to one triangulation
  auto ranksOf = [&](Delaunay::Cell_handle c) {
    std::array<Index, 4> r;
    for (int k = 0; k < 4; ++k) {
      const auto v = c->vertex(k);
      r[k] = dt.is_infinite(v) ? kInvalidIndex : rank[v->info()];
    }
    return r;
  };
  // Every cell around a seed it owns is certified; a left-out seed in
  // conflict with one is inserted (near the domain's boundary the
  // triangulation has long flat cells), and the new cells (those around the
  // inserted seeds) are certified in turn.
  std::size_t added = 0;
  std::vector<Index> more;  // places in `out`
  auto certify = [&](Delaunay::Cell_handle c) {
    bool owns = false;
    for (int k = 0; k < 4; ++k) {
      const auto v = c->vertex(k);
      owns |= !dt.is_infinite(v) && owner_of_seed[v->info()] == s;
    }
    if (!owns) return;
    if (const Index k = conflict(dt, c, out); k != kInvalidIndex && !out.inserted[k]) {
      out.inserted[k] = 1;
      more.push_back(k);
    }
  };
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) certify(c);
  std::vector<Delaunay::Vertex_handle> inserted;
  std::vector<Delaunay::Cell_handle> around;
  while (!more.empty()) {
    added += more.size();
    if (added > kept.size() / 8) return;  // left to one triangulation
    std::sort(more.begin(), more.end(), [&](Index a, Index b) { return rank[out.seed[a]] < rank[out.seed[b]]; });
    inserted.clear();
    Delaunay::Vertex_handle hint;
    for (Index k : more) {
      hint = dt.insert(out.points[k], hint);
      hint->info() = out.seed[k];
      inserted.push_back(hint);
    }
    if (dt.number_of_vertices() != kept.size() + added) return;
    more.clear();
    around.clear();
    for (const auto v : inserted) dt.incident_cells(v, std::back_inserter(around));
    for (const auto c : around) certify(c);
  }
  std::vector<Delaunay::Cell_handle> cells;
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    const std::array<Index, 4> r = ranksOf(c);
    const Index lowest = *std::min_element(r.begin(), r.end());
    if (owner_of_rank[lowest] != s) {
      c->info() = kInvalidIndex;
      continue;
    }
    c->info() = static_cast<Index>(cells.size());
    cells.push_back(c);
    h.tv.push_back(r);
    h.finite.push_back(!dt.is_infinite(c));
  }
  h.tn.resize(cells.size());
  for (std::size_t u = 0; u < cells.size(); ++u) {
    const Delaunay::Cell_handle c = cells[u];
    for (int k = 0; k < 4; ++k) {
      const Delaunay::Cell_handle nb = c->neighbor(k);
      h.tn[u][k] = nb->info();
      if (nb->info() != kInvalidIndex) continue;
      std::array<Index, 3> facet;
      for (int m = 0, f = 0; m < 4; ++m)
        if (m != k) facet[f++] = h.tv[u][m];
      std::sort(facet.begin(), facet.end());
      h.pending.push_back({static_cast<Index>(u), k, facet});
      h.border.emplace_back(facet, static_cast<Index>(u));
    }
  }
  std::sort(h.border.begin(), h.border.end());
  h.ok = true;
}

// The triangulation of all seeds from two halves (split at the median x, each
// with the other's seeds within a margin) triangulated side by side, or
// nothing when a cell cannot be certified or a neighbour is not found (then
// one triangulation is built: the split changes speed, never the result).
std::optional<RawTets> triangulateSplit(std::span<const Vec3> seeds, const std::vector<Point>& points,
                                        const Tetrahedra& tets) {
  const std::size_t n = seeds.size();
  std::vector<double> xs(n);
  Vec3 lo = seeds[0], hi = seeds[0];
  for (std::size_t i = 0; i < n; ++i) {
    xs[i] = seeds[i].x();
    lo = lo.cwiseMin(seeds[i]);
    hi = hi.cwiseMax(seeds[i]);
  }
  std::nth_element(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(n / 2), xs.end());
  const double split = xs[n / 2];
  const double margin = kSplitMargin3 * std::cbrt((hi - lo).prod() / static_cast<double>(n));
  if (!(margin > 0) || split - margin <= lo.x() || split + margin >= hi.x()) return std::nullopt;
  std::vector<std::uint8_t> owner_of_rank(n), owner_of_seed(n);  // 0: x <= split, 1: beyond
  for (std::size_t q = 0; q < n; ++q) {
    const Index i = tets.order[q];
    const double x = seeds[i].x();
    owner_of_rank[q] = owner_of_seed[i] = x <= split ? 0 : 1;
  }
  std::array<Half, 2> half;
#pragma omp parallel for num_threads(2) schedule(static, 1)
  for (int s = 0; s < 2; ++s) {
    std::vector<Index> mine, left_out;
    for (std::size_t q = 0; q < n; ++q) {
      const Index i = tets.order[q];
      const double x = seeds[i].x();
      const bool keep = s == 0 ? x <= split + margin : x >= split - margin;
      (keep ? mine : left_out).push_back(i);
    }
    try {
      LeftOut out(seeds, points, left_out);
      buildHalf(s, points, mine, out, tets.rank, owner_of_rank, owner_of_seed, half[s]);
    } catch (...) {  // (none expected) left to one triangulation, which reports it
      half[s].ok = false;
    }
  }
  if (!half[0].ok || !half[1].ok) return std::nullopt;
  const std::array<Index, 2> offset{0, static_cast<Index>(half[0].tv.size())};
  std::array<std::uint8_t, 2> found{1, 1};
  RawTets raw;
  const std::size_t nt = half[0].tv.size() + half[1].tv.size();
  raw.tv.resize(nt);
  raw.tn.resize(nt);
  raw.finite.resize(nt);
#pragma omp parallel for num_threads(2) schedule(static, 1)
  for (int s = 0; s < 2; ++s) {
    Half& h = half[s];
    const Half& other = half[1 - s];
    for (std::size_t u = 0; u < h.tv.size(); ++u) {
      raw.tv[offset[s] + u] = h.tv[u];
      raw.finite[offset[s] + u] = h.finite[u];
      for (int k = 0; k < 4; ++k)
        raw.tn[offset[s] + u][k] = h.tn[u][k] == kInvalidIndex ? kInvalidIndex : h.tn[u][k] + offset[s];
    }
    for (const Half::Pending& p : h.pending) {
      const auto it = std::lower_bound(other.border.begin(), other.border.end(), std::make_pair(p.key, Index{0}));
      if (it == other.border.end() || it->first != p.key) {
        found[s] = 0;
        break;
      }
      raw.tn[offset[s] + p.cell][p.slot] = offset[1 - s] + it->second;
    }
    h.dt.reset();
  }
  if (!found[0] || !found[1]) return std::nullopt;
  return raw;
}

// The seeds' ranks (order, rank, seeds by rank) of a Tetrahedra.
Tetrahedra ranked(std::span<const Vec3> seeds, std::vector<Point>& points) {
  const std::size_t n = seeds.size();
  const std::int64_t ns = static_cast<std::int64_t>(n);
  Tetrahedra tets;
  tets.order = spatialOrder(seeds, points);
  tets.rank.resize(n);
  tets.seeds.resize(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t q = 0; q < ns; ++q) {
    tets.rank[tets.order[q]] = static_cast<Index>(q);
    tets.seeds[q] = seeds[tets.order[q]];
  }
  return tets;
}

Tetrahedra tetrahedra(std::span<const Vec3> seeds) {
  const std::size_t n = seeds.size();
  std::vector<Point> points;
  Tetrahedra tets = ranked(seeds, points);
  std::optional<RawTets> raw;
  if (n >= kSplitMinSeeds3 && omp_get_max_threads() >= 2) raw = triangulateSplit(seeds, points, tets);
  if (!raw) {
    Delaunay dt;
    triangulateWhole(dt, seeds, points, tets.order);
    raw = readWhole(dt, tets.rank);
  }
  numberCanonically(*raw, n, tets);
  incidence(tets, n);
  return tets;
}

// --- clipVoronoi3, phase 2: the dual arrays ---------------------------------------

// The Voronoi vertices before welding: one circumcentre per finite cell,
// whether it lies inside the domain by the interior margin, and its weld
// group: adjacent cells with (nearly) equal circumcentres are one vertex,
// named by the group's lowest cell.
struct DualVertices3 {
  std::vector<Vec3> cc;
  std::vector<std::uint8_t> inside;
  std::vector<Index> group;
  std::vector<std::uint8_t> grouped;  // welded to another cell (a group of more than one)
};

void computeCircumcentres(std::span<const Vec3> seeds, const ConvexDomain3& domain, const Tetrahedra& tets,
                          DualVertices3& dual) {
  const double margin = kInteriorMargin * domain.scale;
  auto inside = [&](const Vec3& p) {
    if (domain.is_box)
      return (p.array() > domain.lo.array() + margin).all() && (p.array() < domain.hi.array() - margin).all();
    if ((p - domain.center).norm() < domain.inner_radius - margin) return true;
    return domain.excess(p) < -margin;
  };
  dual.cc.assign(tets.size(), Vec3::Zero());
  dual.inside.assign(tets.size(), 0);  // finite and inside the domain by the margin
  const std::int64_t nts = static_cast<std::int64_t>(tets.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t t = 0; t < nts; ++t) {
    if (!tets.finite[t]) continue;
    std::array<Index, 4> g = tets.tv[t];
    std::sort(g.begin(), g.end(), [&](Index a, Index b) { return tets.order[a] < tets.order[b]; });
    dual.cc[t] = planesPoint(g, {}, seeds, domain);
    dual.inside[t] = inside(dual.cc[t]);
  }
}

void groupCloseCircumcentres(const Tetrahedra& tets, double weld, DualVertices3& dual) {
  const std::size_t nt = tets.size();
  std::vector<Index>& group = dual.group;
  group.resize(nt);
  dual.grouped.assign(nt, 0);
  for (std::size_t t = 0; t < nt; ++t) group[t] = static_cast<Index>(t);
  auto root = [&](Index t) {
    while (group[t] != t) t = group[t] = group[group[t]];
    return t;
  };
  for (std::size_t t = 0; t < nt; ++t) {
    if (!tets.finite[t]) continue;
    for (Index u : tets.tn[t]) {
      if (u < t || !tets.finite[u] || (dual.cc[t] - dual.cc[u]).squaredNorm() > weld * weld) continue;
      const Index a = root(static_cast<Index>(t)), b = root(u);
      group[std::max(a, b)] = std::min(a, b);
      dual.grouped[t] = dual.grouped[u] = 1;
    }
  }
  for (std::size_t t = 0; t < nt; ++t) group[t] = root(static_cast<Index>(t));
}

// --- clipVoronoi3, phase 3: reading (interior) or clipping (boundary) each cell ---

// What reading the cells found, per seed.
struct CellReadout3 {
  // Complex output only: the walls, in one store per thread (and the last
  // for the welded boundary cells). Boundary cells first list clipped
  // vertices (canonical positions) their walls number locally, welded
  // (sequentially) by weldBoundaryCells.
  std::vector<WallStore> stores;
  std::vector<CellWallsRef> walls;
  std::vector<std::uint8_t> is_boundary;
  std::vector<std::uint8_t> closed;  // read off the triangulation, no tetrahedron around it grouped
  std::vector<std::string> errors;
  std::vector<Index> duplicate;  // the lowest seed closer than the duplicate distance (by rank)
};

// One cell at a time, from any thread: each writes only its own cell's slots.
// Cells, neighbours and labels are ranks (tets.seeds); the centroids and the
// messages name seeds.
struct CellReader3 {
  std::span<const Vec3> seeds;  // by rank
  const ConvexDomain3& domain;
  const Tetrahedra& tets;
  const DualVertices3& dual;
  bool complex;
  double d2;  // squared duplicate distance
  double on;  // clipping tolerance
  // The ball starts from a box a little larger than its bounding box, so that
  // the icosphere's faces cut every box face away.
  Vec3 margin_box;
  std::array<int, 6> box_labels;
  CellReadout3& readout;
  ClippedCells3& out;

  struct Scratch {
    ClipPolytope cell;
    std::vector<Index> nbrs, first_tet, loop;
    std::vector<std::pair<Index, Index>> pairs;  // (neighbour, the lowest cell around the edge to it)
    std::vector<std::pair<double, Index>> by_distance;  // (squared distance, neighbour): clipping order
    std::vector<Index> seen_by;                  // the last cell that listed rank j (never cleared)
    WallStore* store = nullptr;                  // this thread's (complex output), else `local`
    WallStore local;
  };

  // The seed's Delaunay neighbours (sorted) into s.nbrs, with one cell around
  // the edge to each (the lowest) in s.first_tet; whether every cell around
  // the seed has its circumcentre inside the domain (the cell is interior).
  bool neighbours(Index i, Scratch& s) const {
    bool interior = true;
    std::uint8_t grouped = 0;
    if (s.seen_by.empty()) s.seen_by.assign(seeds.size(), kInvalidIndex);
    s.pairs.clear();
    for (Index k = tets.inc_start[i]; k < tets.inc_start[i + 1]; ++k) {  // cells ascending
      const Index t = tets.inc[k];
      if (!dual.inside[t]) interior = false;
      grouped |= dual.grouped[t];
      for (Index v : tets.tv[t])
        if (v != kInvalidIndex && v != i && s.seen_by[v] != i) {
          s.seen_by[v] = i;
          s.pairs.emplace_back(v, t);
        }
    }
    std::sort(s.pairs.begin(), s.pairs.end());
    s.nbrs.clear();
    s.first_tet.clear();
    for (const auto& [j, t] : s.pairs) {
      s.nbrs.push_back(j);
      s.first_tet.push_back(t);
    }
    for (Index j : s.nbrs)  // the lowest seed index, as seed order would find it
      if ((seeds[j] - seeds[i]).squaredNorm() < d2 && tets.order[j] < readout.duplicate[i])
        readout.duplicate[i] = tets.order[j];
    readout.closed[i] = interior && !grouped;  // (readInterior clears it for a cell without volume)
    return interior;
  }

  // The wall between seeds i and j: the weld groups of the cells around the
  // Delaunay edge ij, starting from the cell t0 around it, counter-clockwise
  // seen from j (its normal points from i to j). Every finite cell of CGAL's
  // triangulation lists its vertices in positive orientation, so
  // orientation(i, j, a, b) is the parity of the permutation of their slots:
  // combinatorial, no predicate.
  void wallLoop(Index i, Index j, Index t0, std::vector<Index>& loop) const {
    int slot[4], m = 2;
    for (int k = 0; k < 4; ++k) {
      const Index v = tets.tv[t0][k];
      if (v == i) slot[0] = k;
      else if (v == j) slot[1] = k;
      else slot[m++] = k;
    }
    int inversions = 0;
    for (int x = 0; x < 4; ++x)
      for (int y = x + 1; y < 4; ++y) inversions += slot[x] > slot[y];
    // Stepping out of t0 through the facet opposite a turns from a towards b.
    Index a = tets.tv[t0][slot[inversions % 2 == 0 ? 2 : 3]];
    loop.clear();
    Index t = t0;
    // Every cell around an edge of an interior cell is finite: its vertices
    // are i, j, a and the next a (their sum less the other three, mod 2^32),
    // found without a branch.
    const Index ij = i + j;
    do {
      const Index g = dual.group[t];
      if (loop.empty() || loop.back() != g) loop.push_back(g);
      const std::array<Index, 4>& v = tets.tv[t];
      const int ka = (v[1] == a) + 2 * (v[2] == a) + 3 * (v[3] == a);
      const Index next_b = v[0] + v[1] + v[2] + v[3] - a - ij;
      t = tets.tn[t][ka];
      a = next_b;
    } while (t != t0);
  }

  // An interior cell: its walls read off the triangulation, its centroid from
  // the cones of its walls' fans to the seed.
  void readInterior(Index i, Scratch& s) const {
    const Vec3& seed = seeds[i];
    WallStore& local = s.store ? *s.store : s.local;
    const std::size_t first = local.size();
    double v6 = 0;
    Vec3 moment = Vec3::Zero();
    for (std::size_t q = 0; q < s.nbrs.size(); ++q) {
      const Index j = s.nbrs[q];
      wallLoop(i, j, s.first_tet[q], s.loop);
      const std::size_t before = local.labels.size();
      local.add(static_cast<int>(j), s.loop);
      if (local.labels.size() == before) continue;
      const Index* w = local.keys.data() + local.starts[before];
      const std::size_t wm = local.starts[before + 1] - local.starts[before];
      const Vec3 q0 = dual.cc[w[0]] - seed;
      for (std::size_t k = 1; k + 1 < wm; ++k) {
        const Vec3 q1 = dual.cc[w[k]] - seed, q2 = dual.cc[w[k + 1]] - seed;
        const double d = q0.dot(q1.cross(q2));
        v6 += d;
        moment += d * (q0 + q1 + q2) / 4;
      }
    }
    const std::size_t count = local.size() - first;
    if (count < 4 || !(v6 > 0)) {
      readout.errors[i] = "the Voronoi cell of " + describeSeed(tets.order[i], seed) + " has no volume";
      readout.closed[i] = 0;
      local.truncate(first);
      return;
    }
    out.centroids[tets.order[i]] = seed + moment / v6;
    if (complex) {
      CellWallsRef& r = readout.walls[i];
      r.store = static_cast<Index>(s.store - readout.stores.data());
      r.first = static_cast<Index>(first);
      r.count = static_cast<Index>(count);
    } else {
      local.truncate(first);
    }
  }

  // A boundary cell: the domain (or the ball's scaffold box) cut by the
  // bisector plane of every Delaunay neighbour, then by the ball's faces.
  void clip(Index i, Scratch& s) const {
    const Vec3& seed = seeds[i];
    readout.is_boundary[i] = 1;
    ClipPolytope& cell = s.cell;
    cell.resetToBox(domain.lo - margin_box, domain.hi + margin_box, box_labels);
    // Nearest first: the cell shrinks early, so later planes cut less or nothing.
    s.by_distance.clear();
    for (Index x : s.nbrs) s.by_distance.emplace_back((seeds[x] - seed).squaredNorm(), x);
    std::sort(s.by_distance.begin(), s.by_distance.end());
    for (std::size_t k = 0; k < s.nbrs.size(); ++k) s.nbrs[k] = s.by_distance[k].second;
    try {
      for (Index v : s.nbrs) {
        const Vec3& t = seeds[v];
        const Vec3 normal = (t - seed).normalized();
        cell.clip(normal, normal.dot((seed + t) / 2), static_cast<int>(v), on);
      }
      if (!domain.is_box) {
        const double reach = cell.reach(seed);
        if ((seed - domain.center).norm() + reach >= domain.inner_radius) {
          for (std::size_t k = 0; k < domain.faces.size(); ++k) {
            const HalfSpace& hs = domain.faces[k];
            if (hs.offset - hs.normal.dot(seed) < reach + on) cell.clip(hs.normal, hs.offset, domainLabel(k), on);
          }
        }
      }
    } catch (const GeometryError& e) {
      readout.errors[i] = "the Voronoi cell of " + describeSeed(tets.order[i], seed) + ": " + e.what();
      return;
    }
    if (cell.numFaces() < 4) {
      readout.errors[i] =
          "the Voronoi cell of " + describeSeed(tets.order[i], seed) + " vanished when clipped to the domain";
      return;
    }
    double volume = 0;
    cell.volumeAndCentroid(volume, out.centroids[tets.order[i]]);
    if (complex) boundaryWalls(i, cell, *s.store);
  }

  // A clipped cell's walls with local vertex numbers, welded later.
  void boundaryWalls(Index i, const ClipPolytope& cell, WallStore& store) const {
    CellWallsRef& r = readout.walls[i];
    r.store = static_cast<Index>(&store - readout.stores.data());
    r.first = static_cast<Index>(store.size());
    r.first_point = static_cast<Index>(store.points.size());
    r.num_points = static_cast<Index>(cell.vertices().size());
    for (std::size_t v = 0; v < cell.vertices().size(); ++v)
      store.points.push_back(
          canonicalPosition(cell.vertices()[v], i, cell.vertexLabels(v), seeds, tets.order, domain));
    for (std::size_t f = 0; f < cell.numFaces(); ++f) {
      if (cell.faceLabel(f) == kScaffoldLabel) {
        readout.errors[i] =
            "the Voronoi cell of " + describeSeed(tets.order[i], seeds[i]) + " was not closed by the ball's faces";
        break;
      }
      store.labels.push_back(cell.faceLabel(f));
      for (const int* v = cell.faceBegin(f); v != cell.faceEnd(f); ++v) store.keys.push_back(static_cast<Index>(*v));
      store.starts.push_back(static_cast<Index>(store.keys.size()));
    }
    r.count = static_cast<Index>(store.size() - r.first);
  }
};

Vec3 scaffoldMargin(const ConvexDomain3& domain) {
  return domain.is_box ? Vec3::Zero() : Vec3::Constant(0.01 * domain.scale);
}

CellReadout3 readCells(std::span<const Vec3> seeds, const ConvexDomain3& domain, double duplicate_tolerance,
                       bool complex, const Tetrahedra& tets, const DualVertices3& dual, ClippedCells3& out) {
  const std::size_t n = seeds.size();
  CellReadout3 readout;
  readout.walls.resize(complex ? n : 0);
  // One store per thread, and the welded boundary cells' (reserved for a
  // uniform share of ~16 walls of ~5 vertices per cell: untouched pages cost nothing).
  const std::size_t threads = static_cast<std::size_t>(omp_get_max_threads());
  if (complex) {
    readout.stores.resize(threads + 1);
    for (std::size_t k = 0; k < threads; ++k) {
      readout.stores[k].labels.reserve(20 * n / threads + 64);
      readout.stores[k].starts.reserve(20 * n / threads + 64);
      readout.stores[k].keys.reserve(110 * n / threads + 320);
    }
  }
  readout.is_boundary.assign(n, 0);
  readout.closed.assign(n, 0);
  readout.errors.resize(n);
  readout.duplicate.assign(n, kInvalidIndex);
  const int scaffold = kScaffoldLabel;
  const CellReader3 reader{
      seeds, domain, tets, dual, complex, std::pow(duplicate_tolerance * domain.scale, 2),
      kOnTolerance * domain.scale, scaffoldMargin(domain),
      domain.is_box ? std::array<int, 6>{-1, -2, -3, -4, -5, -6}
                    : std::array<int, 6>{scaffold, scaffold, scaffold, scaffold, scaffold, scaffold},
      readout, out};
  const std::int64_t ns = static_cast<std::int64_t>(n);
#pragma omp parallel
  {
    CellReader3::Scratch scratch;
    if (complex) scratch.store = &readout.stores[static_cast<std::size_t>(omp_get_thread_num()) % threads];
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t q = 0; q < ns; ++q) {
      const Index i = static_cast<Index>(q);
      if (reader.neighbours(i, scratch))
        reader.readInterior(i, scratch);
      else
        reader.clip(i, scratch);
    }
  }
  return readout;
}

// The first error in seed order.
void throwCellErrors(std::span<const Vec3> seeds, const Tetrahedra& tets, const CellReadout3& readout) {
  for (std::size_t k = 0; k < seeds.size(); ++k)
    if (readout.duplicate[tets.rank[k]] != kInvalidIndex) throwDuplicate(seeds, k, readout.duplicate[tets.rank[k]]);
  for (std::size_t k = 0; k < seeds.size(); ++k)
    if (!readout.errors[tets.rank[k]].empty()) throw GeometryError(readout.errors[tets.rank[k]]);
}

// --- clipVoronoi3, phase 4: welding the boundary cells' vertices -------------------

// Keys: a cell group (< nt), or nt + k for the k-th point made by clipping.
// Clipped points weld onto the circumcentres of the boundary seeds' cells
// first (except those on the boundary, left to the clipped points), then onto
// each other. Rewrites the boundary cells' walls in keys; returns the points
// made by clipping.
std::vector<Vec3> weldBoundaryCells(const ConvexDomain3& domain, const Tetrahedra& tets, const DualVertices3& dual,
                                    CellReadout3& readout) {
  const std::size_t n = readout.is_boundary.size(), nt = tets.size();
  const double weld = kWeldTolerance * domain.scale;
  VertexWelder welder(domain.lo - scaffoldMargin(domain), weld, 0);
  std::vector<Index> key_of_weld;
  std::vector<Vec3> extra;
  // A cell around several boundary seeds is welded at its first visit (again
  // it would find its own point and add nothing).
  std::vector<std::uint8_t> visited(nt, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!readout.is_boundary[i]) continue;
    for (Index k = tets.inc_start[i]; k < tets.inc_start[i + 1]; ++k) {
      const Index t = tets.inc[k];
      if (visited[t]) continue;
      visited[t] = 1;
      if (!tets.finite[t] || domain.excess(dual.cc[t]) > -2 * weld) continue;  // see 2D
      const Index w = welder.weld(dual.cc[t]);
      if (w == key_of_weld.size()) key_of_weld.push_back(dual.group[t]);
    }
  }
  std::vector<Index> local_key, loop;
  WallStore& welded = readout.stores.back();
  const Index welded_store = static_cast<Index>(readout.stores.size() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    if (!readout.is_boundary[i]) continue;
    CellWallsRef& r = readout.walls[i];
    const WallStore& from = readout.stores[r.store];
    local_key.clear();
    for (Index k = r.first_point; k < r.first_point + r.num_points; ++k) {
      const Vec3& p = from.points[k];
      const Index w = welder.weld(p);
      if (w == key_of_weld.size()) {
        key_of_weld.push_back(static_cast<Index>(nt + extra.size()));
        extra.push_back(p);
      }
      local_key.push_back(key_of_weld[w]);
    }
    const CellWalls raw(readout.stores, r);
    const Index first = static_cast<Index>(welded.size());
    for (std::size_t f = 0; f < raw.size(); ++f) {
      loop.clear();
      for (Index k : raw.loop(f)) {
        const Index g = local_key[k];
        if (loop.empty() || loop.back() != g) loop.push_back(g);
      }
      welded.add(raw.labels[f], loop);
    }
    r = CellWallsRef{welded_store, first, static_cast<Index>(welded.size() - first), 0, 0};
  }
  return extra;
}

// --- clipVoronoi3, phase 5: the walls and cells of the tissue ----------------------

// A wall between the cells of ranks i < j is stored once, by i (normal
// towards j), and used reversed by j, which must list exactly the reverse
// loop (the same keys), or a GeometryError names the two seeds. Faces are
// numbered along the ranks (CGAL's Hilbert order), each cell's stored walls
// in its own order, and vertices by first use in that face list: consecutive
// faces and their vertices lie close together, so building the complex
// streams through memory. Cell k is seed k. Counting, writing the loops and
// listing each cell's faces run in parallel; only the vertex numbering (one
// pass over the loops) is sequential.
void assembleCells(std::span<const Vec3> seeds, const Tetrahedra& tets, const DualVertices3& dual,
                   const std::vector<Vec3>& extra, const std::vector<WallStore>& wall_stores,
                   const std::vector<CellWallsRef>& refs, std::span<const std::uint8_t> closed, ClippedCells3& out) {
  const std::vector<WallStore>& stores_ = wall_stores;
  const std::size_t n = seeds.size(), nt = dual.cc.size();
  const std::int64_t ns = static_cast<std::int64_t>(n);
  auto stores = [](int label, std::size_t i) { return label < 0 || static_cast<std::size_t>(label) > i; };
  auto wallsOf = [&](Index i) { return CellWalls(stores_, refs[i]); };
  // Per rank: stored walls and their keys.
  std::vector<Index> face_start(n + 1, 0), key_start(n + 1, 0);
#pragma omp parallel for schedule(static)
  for (std::int64_t q = 0; q < ns; ++q) {
    const Index i = static_cast<Index>(q);
    const CellWalls cw = wallsOf(i);
    Index nf = 0, nk = 0;
    for (std::size_t f = 0; f < cw.size(); ++f)
      if (stores(cw.labels[f], i)) {
        ++nf;
        nk += cw.starts[f + 1] - cw.starts[f];
      }
    face_start[q + 1] = nf;
    key_start[q + 1] = nk;
  }
  for (std::size_t q = 0; q < n; ++q) {
    face_start[q + 1] += face_start[q];
    key_start[q + 1] += key_start[q];
  }
  const std::size_t nfaces = face_start[n];
  // The first face rank i stores (its walls' face ids follow in order).
  std::vector<Index> first_face(n);
  out.face_offsets.resize(nfaces + 1);
  out.face_offsets[nfaces] = key_start[n];
  out.face_loops.resize(key_start[n]);
#pragma omp parallel for schedule(static)
  for (std::int64_t q = 0; q < ns; ++q) {
    const Index i = static_cast<Index>(q);
    const CellWalls cw = wallsOf(i);
    first_face[i] = face_start[q];
    Index face = face_start[q], at = key_start[q];
    for (std::size_t f = 0; f < cw.size(); ++f) {
      if (!stores(cw.labels[f], i)) continue;
      out.face_offsets[face++] = at;
      for (Index k = cw.starts[f]; k < cw.starts[f + 1]; ++k) out.face_loops[at++] = cw.keys[k];
    }
  }
  // Vertices by first use along the face list.
  std::vector<Index> id(nt + extra.size(), kInvalidIndex);
  std::vector<Index> key_of_id;
  key_of_id.reserve(nt / 2 + extra.size());
  for (Index& k : out.face_loops) {
    if (id[k] == kInvalidIndex) {
      id[k] = static_cast<Index>(key_of_id.size());
      key_of_id.push_back(k);
    }
    k = id[k];
  }
  out.positions.resize(key_of_id.size());
  const std::int64_t nvs = static_cast<std::int64_t>(key_of_id.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t v = 0; v < nvs; ++v) {
    const Index k = key_of_id[v];
    out.positions[v] = k < nt ? dual.cc[k] : extra[k - nt];
  }
  // Cells in seed order; a wall towards a lower neighbour j is j's stored
  // face towards i, which must be the same loop reversed; a stored wall
  // towards a higher neighbour must be listed by it.
  out.cell_offsets.assign(n + 1, 0);
  out.closed.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    out.cell_offsets[k + 1] = out.cell_offsets[k] + refs[tets.rank[k]].count;
    out.closed[k] = closed[tets.rank[k]];
  }
  out.cell_faces.resize(out.cell_offsets[n]);
  // Per rank: the first lower neighbour whose wall differs, the first higher one missing a stored wall.
  std::vector<Index> differs_from(n, kInvalidIndex), missing_in(n, kInvalidIndex);
  // Whether a cell's labels ascend (an interior cell lists its walls by
  // neighbour rank): then a binary search finds a wall.
  std::vector<std::uint8_t> ascending(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t q = 0; q < ns; ++q) {
    const CellWalls cw = wallsOf(static_cast<Index>(q));
    ascending[q] = std::is_sorted(cw.labels.begin(), cw.labels.end(), std::less_equal<int>());
  }
  // The position of the wall towards `label` in cell j's list, or -1.
  auto wallTowards = [&](Index j, Index label) -> std::ptrdiff_t {
    const std::span<const int> labels = wallsOf(j).labels;
    const int l = static_cast<int>(label);
    const auto it = ascending[j] ? std::lower_bound(labels.begin(), labels.end(), l)
                                 : std::find(labels.begin(), labels.end(), l);
    return it == labels.end() || *it != l ? -1 : it - labels.begin();
  };
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t q = 0; q < ns; ++q) {
    const Index i = static_cast<Index>(q);
    const CellWalls cw = wallsOf(i);
    Index own = first_face[i];
    CellFace* list = out.cell_faces.data() + out.cell_offsets[tets.order[i]];
    for (std::size_t f = 0; f < cw.size(); ++f) {
      const int label = cw.labels[f];
      // Two cells closed by construction (read off the triangulation, no
      // welded vertex) list each other, and their walls are one walk around
      // the Delaunay edge from its lowest cell, in opposite senses: the same
      // loop reversed. Only walls with another cell are compared.
      const bool both_read = label >= 0 && closed[i] && closed[static_cast<Index>(label)];
      if (stores(label, i)) {
        list[f] = {own++, false};
        if (label >= 0 && !both_read && missing_in[i] == kInvalidIndex &&
            wallTowards(static_cast<Index>(label), i) < 0)
          missing_in[i] = static_cast<Index>(label);
        continue;
      }
      const Index j = static_cast<Index>(label);
      const std::ptrdiff_t g = wallTowards(j, i);
      Index face = kInvalidIndex;
      if (g >= 0) {
        // j's stored walls before g give the face id: its walls towards the
        // domain and towards higher ranks (when its labels ascend, those
        // below 0 and those in (j, i)).
        const CellWalls wj = wallsOf(j);
        face = first_face[j];
        if (ascending[j]) {
          const auto b = wj.labels.begin();
          face += static_cast<Index>((std::lower_bound(b, b + g, 0) - b) +
                                     (g - (std::upper_bound(b, b + g, static_cast<int>(j)) - b)));
        } else {
          for (std::ptrdiff_t h = 0; h < g; ++h)
            if (stores(wj.labels[h], j)) ++face;
        }
        if (!both_read && !reverseOf(wj.loop(static_cast<std::size_t>(g)), cw.loop(f))) face = kInvalidIndex;
      }
      if (face == kInvalidIndex) {
        if (differs_from[i] == kInvalidIndex) differs_from[i] = j;
        face = 0;
      }
      list[f] = {face, true};
    }
  }
  // The first error in seed order.
  auto seed = [&](Index rank) { return describeSeed(tets.order[rank], seeds[tets.order[rank]]); };
  for (std::size_t k = 0; k < n; ++k)
    if (const Index i = tets.rank[k]; differs_from[i] != kInvalidIndex)
      throw GeometryError("the wall between the Voronoi cells of " + seed(differs_from[i]) + " and " + seed(i) +
                          " comes out differently from the two cells (nearly degenerate seeds)");
  for (std::size_t k = 0; k < n; ++k)
    if (const Index i = tets.rank[k]; missing_in[i] != kInvalidIndex)
      throw GeometryError("a wall of the Voronoi cell of " + seed(i) + " is missing from its neighbour " +
                          seed(missing_in[i]) + " (nearly degenerate seeds)");
}

}  // namespace

bool triangulatesInHalves3(std::span<const Vec3> seeds) {
  std::vector<Point> points;
  const Tetrahedra tets = ranked(seeds, points);
  return triangulateSplit(seeds, points, tets).has_value();
}

ClippedCells3 clipVoronoi3(std::span<const Vec3> seeds, const ConvexDomain3& domain,
                           double duplicate_tolerance, CellOutput output) {
  const Tetrahedra tets = tetrahedra(seeds);
  DualVertices3 dual;
  computeCircumcentres(tets.seeds, domain, tets, dual);
  groupCloseCircumcentres(tets, kWeldTolerance * domain.scale, dual);
  const bool complex = output == CellOutput::Complex;
  ClippedCells3 out;
  out.centroids.resize(seeds.size());
  CellReadout3 readout = readCells(tets.seeds, domain, duplicate_tolerance, complex, tets, dual, out);
  throwCellErrors(seeds, tets, readout);
  if (!complex) return out;
  const std::vector<Vec3> extra = weldBoundaryCells(domain, tets, dual, readout);
  assembleCells(seeds, tets, dual, extra, readout.stores, readout.walls, readout.closed, out);
  return out;
}

}  // namespace detail

namespace {

template <typename Domain>
Tissue solidVoronoi(std::span<const Vec3> seeds, const Domain& d, const VoronoiOptions& options) {
  detail::checkOptions(options);
  const detail::ConvexDomain3 domain = detail::makeDomain(d);
  detail::checkSeeds3(seeds, domain);
  std::vector<Vec3> relaxed;
  if (options.lloyd_iterations > 0) {
    relaxed = detail::lloydRelax(seeds, domain, options.lloyd_iterations, options.duplicate_tolerance);
    seeds = relaxed;
  }
  detail::ClippedCells3 cells =
      detail::clipVoronoi3(seeds, domain, options.duplicate_tolerance, detail::CellOutput::Complex);
  return buildPolyhedralTissue(std::move(cells.positions), cells.face_offsets, cells.face_loops,
                               cells.cell_offsets, cells.cell_faces, cells.closed);
}

}  // namespace

Tissue voronoiTissue(std::span<const Vec3> seeds, const Box& domain, const VoronoiOptions& options) {
  return solidVoronoi(seeds, domain, options);
}

Tissue voronoiTissue(std::span<const Vec3> seeds, const Ball& domain, const VoronoiOptions& options) {
  return solidVoronoi(seeds, domain, options);
}

}  // namespace tessella
