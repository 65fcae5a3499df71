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
#include <cstdint>
#include <functional>
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
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
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

Delaunay triangulate(std::span<const Vec3> seeds) {
  std::vector<std::pair<Point, Index>> points;
  points.reserve(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i)
    points.emplace_back(Point(seeds[i].x(), seeds[i].y(), seeds[i].z()), static_cast<Index>(i));
  Delaunay dt;
  dt.insert(points.begin(), points.end());  // spatially sorted insertion

  if (dt.number_of_vertices() < seeds.size()) {  // exact duplicates were merged
    std::vector<std::uint8_t> kept(seeds.size(), 0);
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) kept[v->info()] = 1;
    for (std::size_t i = 0; i < seeds.size(); ++i)
      if (!kept[i]) throwDuplicate(seeds, i, dt.nearest_vertex(points[i].first)->info());
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
  return dt;
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
// (Hilbert) insertion order, cells by first appearance around the seeds in
// that order. Random seeds then put neighbouring seeds, their cells and
// circumcentres next to each other in memory, and every pass below streams
// instead of missing the cache at each step. Only the cell list of the tissue
// (cell k = seed k) and the messages go back to seed indices.
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

Tetrahedra tetrahedra(Delaunay& dt, std::span<const Vec3> seeds) {
  const std::size_t n = seeds.size();
  Tetrahedra tets;
  tets.order.reserve(n);
  tets.rank.resize(n);
  tets.seeds.reserve(n);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    tets.rank[v->info()] = static_cast<Index>(tets.order.size());
    tets.order.push_back(v->info());
    tets.seeds.push_back(seeds[v->info()]);
  }
  std::vector<Delaunay::Cell_handle> tet;
  tet.reserve(7 * n);
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    c->info() = static_cast<Index>(tet.size());
    tet.push_back(c);
  }
  const std::size_t nt = tet.size();
  // In CGAL's numbering first. (Reading handles is thread-safe; only CGAL's
  // incidence queries are not.)
  const std::int64_t nts = static_cast<std::int64_t>(nt);
  std::vector<std::array<Index, 4>> tv(nt);
#pragma omp parallel for schedule(static)
  for (std::int64_t t = 0; t < nts; ++t)
    for (int k = 0; k < 4; ++k) {
      const auto v = tet[t]->vertex(k);
      tv[t][k] = dt.is_infinite(v) ? kInvalidIndex : tets.rank[v->info()];
    }
  tets.tv = std::move(tv);
  // Cells renumbered by first appearance along the ranks (every cell has a
  // finite vertex): a cell first appears around its lowest rank, after the
  // cells of lower indices there, so this is a counting sort of the cells by
  // lowest rank, stable in CGAL's numbering.
  std::vector<Index> lowest(nt), start(n + 1, 0);
#pragma omp parallel for schedule(static)
  for (std::int64_t t = 0; t < nts; ++t) {
    Index m = kInvalidIndex;
    for (Index v : tets.tv[t]) m = std::min(m, v);  // kInvalidIndex (infinite) is the largest
    lowest[t] = m;
  }
  for (std::size_t t = 0; t < nt; ++t) ++start[lowest[t] + 1];
  for (std::size_t q = 0; q < n; ++q) start[q + 1] += start[q];
  std::vector<Index> renumber(nt), old_of(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const Index u = start[lowest[t]]++;
    renumber[t] = u;
    old_of[u] = static_cast<Index>(t);
  }
  tv.resize(nt);
  tets.tn.resize(nt);
  tets.finite.resize(nt);
#pragma omp parallel for schedule(static)
  for (std::int64_t u = 0; u < nts; ++u) {
    const Index t = old_of[u];
    tv[u] = tets.tv[t];
    tets.finite[u] = !dt.is_infinite(tet[t]);
    for (int k = 0; k < 4; ++k) tets.tn[u][k] = renumber[tet[t]->neighbor(k)->info()];
  }
  tets.tv = std::move(tv);
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

ClippedCells3 clipVoronoi3(std::span<const Vec3> seeds, const ConvexDomain3& domain,
                           double duplicate_tolerance, CellOutput output) {
  Delaunay dt = triangulate(seeds);
  const Tetrahedra tets = tetrahedra(dt, seeds);
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
