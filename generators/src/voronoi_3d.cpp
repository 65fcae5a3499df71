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
// (reversed) from both cells, or a GeometryError says which. Per-cell work
// runs in parallel; numbering is sequential, so the result does not depend on
// the thread count.

#include <algorithm>
#include <array>
#include <span>
#include <cmath>
#include <cstdint>
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
// canonically (sorted seed indices, domain faces) so that every cell sharing
// the vertex gets the same bits -- clipping interpolates along edges, which
// is ill-conditioned where a bisector grazes an edge (nearly cospherical
// seeds), and different cells would disagree by more than the weld
// tolerance. Falls back to the clipped position if the planes do not pin
// down a point near it. (Not inlined: GCC 12 then warns falsely about the
// bounds of the sorts below.)
[[gnu::noinline]] Vec3 canonicalPosition(const Vec3& clipped, Index cell, std::span<const int> labels,
                       std::span<const Vec3> seeds, const ConvexDomain3& domain) {
  std::array<Index, ClipPolytope::kMaxLabels + 1> generators{};
  std::array<int, ClipPolytope::kMaxLabels> faces{};
  std::size_t ng = 0, nf = 0;
  generators[ng++] = cell;
  for (int l : labels) {
    if (l >= 0) generators[ng++] = static_cast<Index>(l);
    else if (l != kScaffoldLabel) faces[nf++] = -1 - l;
  }
  if (ng - 1 + nf < 3) return clipped;
  std::sort(generators.begin(), generators.begin() + ng);
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

// One wall of a cell before numbering: its label (neighbour seed or domain
// face) and its vertex keys, counter-clockwise seen from outside the cell.
struct CellWalls {
  std::vector<int> labels;
  std::vector<Index> starts{0};
  std::vector<Index> keys;
  void add(int label, std::vector<Index>& loop) {
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    if (loop.size() < 3) return;  // a wall welded to nothing (cospherical seeds)
    labels.push_back(label);
    keys.insert(keys.end(), loop.begin(), loop.end());
    starts.push_back(static_cast<Index>(keys.size()));
  }
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
// vertices (seed indices, kInvalidIndex for the infinite vertex) and
// neighbours, and each seed's cells, are copied out once.
struct Tetrahedra {
  std::vector<std::array<Index, 4>> tv, tn;
  std::vector<std::uint8_t> finite;
  std::vector<Index> inc_start, inc;  // seed i's cells: inc[inc_start[i] .. inc_start[i + 1])
  // Seeds in CGAL's storage order (along its Hilbert sort): cells visited in
  // this order touch nearby memory one after the other.
  std::vector<Index> order;
  std::size_t size() const { return tv.size(); }
};

Tetrahedra tetrahedra(Delaunay& dt, std::size_t n) {
  std::vector<Delaunay::Cell_handle> tet;
  tet.reserve(7 * n);
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    c->info() = static_cast<Index>(tet.size());
    tet.push_back(c);
  }
  const std::size_t nt = tet.size();
  Tetrahedra tets;
  tets.tv.resize(nt);
  tets.tn.resize(nt);
  tets.finite.resize(nt);
  tets.inc_start.assign(n + 1, 0);
  for (std::size_t t = 0; t < nt; ++t) {
    tets.finite[t] = !dt.is_infinite(tet[t]);
    for (int k = 0; k < 4; ++k) {
      const auto v = tet[t]->vertex(k);
      tets.tv[t][k] = dt.is_infinite(v) ? kInvalidIndex : v->info();
      tets.tn[t][k] = tet[t]->neighbor(k)->info();
      if (tets.tv[t][k] != kInvalidIndex) ++tets.inc_start[tets.tv[t][k] + 1];
    }
  }
  for (std::size_t i = 0; i < n; ++i) tets.inc_start[i + 1] += tets.inc_start[i];
  tets.order.reserve(n);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) tets.order.push_back(v->info());
  tets.inc.resize(tets.inc_start[n]);
  std::vector<Index> fill(tets.inc_start.begin(), tets.inc_start.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
    for (Index v : tets.tv[t])
      if (v != kInvalidIndex) tets.inc[fill[v]++] = static_cast<Index>(t);
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
    std::sort(g.begin(), g.end());
    dual.cc[t] = planesPoint(g, {}, seeds, domain);
    dual.inside[t] = inside(dual.cc[t]);
  }
}

void groupCloseCircumcentres(const Tetrahedra& tets, double weld, DualVertices3& dual) {
  const std::size_t nt = tets.size();
  std::vector<Index>& group = dual.group;
  group.resize(nt);
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
    }
  }
  for (std::size_t t = 0; t < nt; ++t) group[t] = root(static_cast<Index>(t));
}

// --- clipVoronoi3, phase 3: reading (interior) or clipping (boundary) each cell ---

// What reading the cells found, per seed.
struct CellReadout3 {
  std::vector<CellWalls> walls;  // complex output only
  // Boundary cells: clipped vertices (canonical positions) their walls number
  // locally, welded (sequentially) by weldBoundaryCells.
  std::vector<std::vector<Vec3>> clipped_points;
  std::vector<std::uint8_t> is_boundary;
  std::vector<std::string> errors;
  std::vector<Index> duplicate;  // a neighbour closer than the duplicate distance
};

// One cell at a time, from any thread: each writes only its own cell's slots.
struct CellReader3 {
  std::span<const Vec3> seeds;
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
    std::vector<Index> nbrs, loop;
    CellWalls local;
  };

  // The seed's Delaunay neighbours (sorted) into s.nbrs; whether every cell
  // around it has its circumcentre inside the domain (the cell is interior).
  bool neighbours(Index i, Scratch& s) const {
    bool interior = true;
    s.nbrs.clear();
    for (Index k = tets.inc_start[i]; k < tets.inc_start[i + 1]; ++k) {
      const Index t = tets.inc[k];
      if (!dual.inside[t]) interior = false;
      for (Index v : tets.tv[t])
        if (v != kInvalidIndex && v != i) s.nbrs.push_back(v);
    }
    std::sort(s.nbrs.begin(), s.nbrs.end());
    s.nbrs.erase(std::unique(s.nbrs.begin(), s.nbrs.end()), s.nbrs.end());
    for (Index j : s.nbrs)
      if ((seeds[j] - seeds[i]).squaredNorm() < d2 && readout.duplicate[i] == kInvalidIndex)
        readout.duplicate[i] = j;
    return interior;
  }

  // The wall between seeds i and j: the weld groups of the cells around the
  // Delaunay edge ij, counter-clockwise seen from j (its normal points from i to j).
  void wallLoop(Index i, Index j, std::vector<Index>& loop) const {
    Index t0 = kInvalidIndex;
    for (Index k = tets.inc_start[i]; k < tets.inc_start[i + 1] && t0 == kInvalidIndex; ++k)
      for (Index v : tets.tv[tets.inc[k]])
        if (v == j) t0 = tets.inc[k];
    std::array<Index, 2> ab{};
    int m = 0;
    for (Index v : tets.tv[t0])
      if (v != i && v != j) ab[m++] = v;
    auto p = [&](Index v) { return Point(seeds[v].x(), seeds[v].y(), seeds[v].z()); };
    // Stepping out of t0 through the facet opposite a turns from a towards b.
    Index a = ab[0];
    if (CGAL::orientation(p(i), p(j), p(ab[0]), p(ab[1])) != CGAL::POSITIVE) a = ab[1];
    loop.clear();
    Index t = t0;
    do {
      const Index g = dual.group[t];
      if (loop.empty() || loop.back() != g) loop.push_back(g);
      int ka = 0;
      while (tets.tv[t][ka] != a) ++ka;
      Index next_b = kInvalidIndex;
      for (Index v : tets.tv[t])
        if (v != i && v != j && v != a) next_b = v;
      t = tets.tn[t][ka];
      a = next_b;
    } while (t != t0);
  }

  // An interior cell: its walls read off the triangulation, its centroid from
  // the cones of its walls' fans to the seed.
  void readInterior(Index i, Scratch& s) const {
    const Vec3& seed = seeds[i];
    CellWalls& local = s.local;
    local = CellWalls{};
    double v6 = 0;
    Vec3 moment = Vec3::Zero();
    for (Index j : s.nbrs) {
      wallLoop(i, j, s.loop);
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
    if (local.labels.size() < 4 || !(v6 > 0)) {
      readout.errors[i] = "the Voronoi cell of " + describeSeed(i, seed) + " has no volume";
      return;
    }
    out.centroids[i] = seed + moment / v6;
    if (complex) readout.walls[i] = std::move(local);
  }

  // A boundary cell: the domain (or the ball's scaffold box) cut by the
  // bisector plane of every Delaunay neighbour, then by the ball's faces.
  void clip(Index i, Scratch& s) const {
    const Vec3& seed = seeds[i];
    readout.is_boundary[i] = 1;
    ClipPolytope& cell = s.cell;
    cell.resetToBox(domain.lo - margin_box, domain.hi + margin_box, box_labels);
    // Nearest first: the cell shrinks early, so later planes cut less or nothing.
    std::sort(s.nbrs.begin(), s.nbrs.end(), [&](Index x, Index y) {
      return std::make_pair((seeds[x] - seed).squaredNorm(), x) < std::make_pair((seeds[y] - seed).squaredNorm(), y);
    });
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
      readout.errors[i] = "the Voronoi cell of " + describeSeed(i, seed) + ": " + e.what();
      return;
    }
    if (cell.numFaces() < 4) {
      readout.errors[i] = "the Voronoi cell of " + describeSeed(i, seed) + " vanished when clipped to the domain";
      return;
    }
    double volume = 0;
    cell.volumeAndCentroid(volume, out.centroids[i]);
    if (complex) boundaryWalls(i, cell);
  }

  // A clipped cell's walls with local vertex numbers, welded later.
  void boundaryWalls(Index i, const ClipPolytope& cell) const {
    CellWalls& cw = readout.walls[i];
    std::vector<Vec3>& pts = readout.clipped_points[i];
    for (std::size_t v = 0; v < cell.vertices().size(); ++v)
      pts.push_back(canonicalPosition(cell.vertices()[v], i, cell.vertexLabels(v), seeds, domain));
    for (std::size_t f = 0; f < cell.numFaces(); ++f) {
      if (cell.faceLabel(f) == kScaffoldLabel) {
        readout.errors[i] = "the Voronoi cell of " + describeSeed(i, seeds[i]) + " was not closed by the ball's faces";
        break;
      }
      cw.labels.push_back(cell.faceLabel(f));
      for (const int* v = cell.faceBegin(f); v != cell.faceEnd(f); ++v) cw.keys.push_back(static_cast<Index>(*v));
      cw.starts.push_back(static_cast<Index>(cw.keys.size()));
    }
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
  readout.clipped_points.resize(complex ? n : 0);
  readout.is_boundary.assign(n, 0);
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
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t q = 0; q < ns; ++q) {
      const Index i = tets.order[q];
      if (reader.neighbours(i, scratch))
        reader.readInterior(i, scratch);
      else
        reader.clip(i, scratch);
    }
  }
  return readout;
}

void throwCellErrors(std::span<const Vec3> seeds, const CellReadout3& readout) {
  for (std::size_t i = 0; i < seeds.size(); ++i)
    if (readout.duplicate[i] != kInvalidIndex) throwDuplicate(seeds, i, readout.duplicate[i]);
  for (std::size_t i = 0; i < seeds.size(); ++i)
    if (!readout.errors[i].empty()) throw GeometryError(readout.errors[i]);
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
  for (std::size_t i = 0; i < n; ++i) {
    if (!readout.is_boundary[i]) continue;
    for (Index k = tets.inc_start[i]; k < tets.inc_start[i + 1]; ++k) {
      const Index t = tets.inc[k];
      if (!tets.finite[t] || domain.excess(dual.cc[t]) > -2 * weld) continue;  // see 2D
      const Index w = welder.weld(dual.cc[t]);
      if (w == key_of_weld.size()) key_of_weld.push_back(dual.group[t]);
    }
  }
  std::vector<Index> local_key, loop;
  for (std::size_t i = 0; i < n; ++i) {
    if (!readout.is_boundary[i]) continue;
    local_key.clear();
    for (const Vec3& p : readout.clipped_points[i]) {
      const Index w = welder.weld(p);
      if (w == key_of_weld.size()) {
        key_of_weld.push_back(static_cast<Index>(nt + extra.size()));
        extra.push_back(p);
      }
      local_key.push_back(key_of_weld[w]);
    }
    CellWalls raw = std::move(readout.walls[i]);
    CellWalls& cw = readout.walls[i];
    cw = CellWalls{};
    for (std::size_t f = 0; f < raw.labels.size(); ++f) {
      loop.clear();
      for (Index k = raw.starts[f]; k < raw.starts[f + 1]; ++k) {
        const Index g = local_key[raw.keys[k]];
        if (loop.empty() || loop.back() != g) loop.push_back(g);
      }
      cw.add(raw.labels[f], loop);
    }
    readout.clipped_points[i] = {};
  }
  return extra;
}

// --- clipVoronoi3, phase 5: the walls and cells of the tissue ----------------------

// The wall a cell lists towards a neighbour that already stored it: the
// stored face, which must be the same loop reversed (GeometryError otherwise).
Index storedWall(std::span<const Vec3> seeds, Index i, Index other, std::span<const Index> keys,
                 const std::vector<std::pair<Index, Index>>& made_by_other, const std::vector<Index>& id,
                 const ClippedCells3& out, std::vector<Index>& scratch) {
  Index face = kInvalidIndex;
  for (const auto& [j, fid] : made_by_other)
    if (j == i) face = fid;
  bool same = face != kInvalidIndex;
  if (same) {
    // Compare in vertex ids: every key of the stored wall has one.
    scratch.clear();
    for (Index k : keys) scratch.push_back(id[k]);
    const std::span<const Index> stored(out.face_loops.data() + out.face_offsets[face],
                                        out.face_offsets[face + 1] - out.face_offsets[face]);
    same = reverseOf(stored, scratch);
  }
  if (!same)
    throw GeometryError("the wall between the Voronoi cells of " + describeSeed(other, seeds[other]) + " and " +
                        describeSeed(i, seeds[i]) +
                        " comes out differently from the two cells (nearly degenerate seeds)");
  return face;
}

// A wall between cells i < j is stored once from i (normal towards j) and
// used reversed by j; vertices are numbered by first use.
void assembleCells(std::span<const Vec3> seeds, const DualVertices3& dual, const std::vector<Vec3>& extra,
                   const std::vector<CellWalls>& walls, ClippedCells3& out) {
  const std::size_t n = seeds.size(), nt = dual.cc.size();
  std::vector<Index> id(nt + extra.size(), kInvalidIndex);
  std::vector<std::vector<std::pair<Index, Index>>> shared(n);  // (j, face) made by i < j
  std::vector<std::uint8_t> matched;
  std::vector<Index> scratch;
  out.cell_offsets.reserve(n + 1);
  out.cell_offsets.push_back(0);
  out.face_offsets.push_back(0);
  for (std::size_t i = 0; i < n; ++i) {
    const CellWalls& cw = walls[i];
    for (std::size_t f = 0; f < cw.labels.size(); ++f) {
      const std::span<const Index> keys(cw.keys.data() + cw.starts[f], cw.starts[f + 1] - cw.starts[f]);
      const int label = cw.labels[f];
      if (label >= 0 && static_cast<std::size_t>(label) < i) {
        const Index other = static_cast<Index>(label);
        const Index face = storedWall(seeds, static_cast<Index>(i), other, keys, shared[other], id, out, scratch);
        matched[face] = 1;
        out.cell_faces.push_back({face, true});
        continue;
      }
      const Index face = static_cast<Index>(out.face_offsets.size() - 1);
      for (Index k : keys) {
        if (id[k] == kInvalidIndex) {
          id[k] = static_cast<Index>(out.positions.size());
          out.positions.push_back(k < nt ? dual.cc[k] : extra[k - nt]);
        }
        out.face_loops.push_back(id[k]);
      }
      out.face_offsets.push_back(static_cast<Index>(out.face_loops.size()));
      out.cell_faces.push_back({face, false});
      matched.push_back(label < 0);
      if (label >= 0) shared[i].emplace_back(static_cast<Index>(label), face);
    }
    out.cell_offsets.push_back(static_cast<Index>(out.cell_faces.size()));
  }
  for (std::size_t i = 0; i < n; ++i)
    for (const auto& [j, face] : shared[i])
      if (!matched[face])
        throw GeometryError("a wall of the Voronoi cell of " + describeSeed(i, seeds[i]) +
                            " is missing from its neighbour " + describeSeed(j, seeds[j]) +
                            " (nearly degenerate seeds)");
}

}  // namespace

ClippedCells3 clipVoronoi3(std::span<const Vec3> seeds, const ConvexDomain3& domain,
                           double duplicate_tolerance, CellOutput output) {
  Delaunay dt = triangulate(seeds);
  const Tetrahedra tets = tetrahedra(dt, seeds.size());
  DualVertices3 dual;
  computeCircumcentres(seeds, domain, tets, dual);
  groupCloseCircumcentres(tets, kWeldTolerance * domain.scale, dual);
  const bool complex = output == CellOutput::Complex;
  ClippedCells3 out;
  out.centroids.resize(seeds.size());
  CellReadout3 readout = readCells(seeds, domain, duplicate_tolerance, complex, tets, dual, out);
  throwCellErrors(seeds, readout);
  if (!complex) return out;
  const std::vector<Vec3> extra = weldBoundaryCells(domain, tets, dual, readout);
  assembleCells(seeds, dual, extra, readout.walls, out);
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
                               cells.cell_offsets, cells.cell_faces);
}

}  // namespace

Tissue voronoiTissue(std::span<const Vec3> seeds, const Box& domain, const VoronoiOptions& options) {
  return solidVoronoi(seeds, domain, options);
}

Tissue voronoiTissue(std::span<const Vec3> seeds, const Ball& domain, const VoronoiOptions& options) {
  return solidVoronoi(seeds, domain, options);
}

}  // namespace tessella
