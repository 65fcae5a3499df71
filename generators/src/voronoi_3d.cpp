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

#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/generators/voronoi.hpp"
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
using CellBase = CGAL::Triangulation_cell_base_with_info_3<Index, Kernel, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
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

}  // namespace

ClippedCells3 clipVoronoi3(std::span<const Vec3> seeds, const ConvexDomain3& domain,
                           double duplicate_tolerance, CellOutput output) {
  Delaunay dt = triangulate(seeds);
  const std::size_t n = seeds.size();

  // The tetrahedralisation as plain arrays (CGAL's incidence queries mark
  // cells and are not thread-safe): vertices (seed indices, kInvalidIndex for
  // the infinite vertex) and neighbours of every cell, and each seed's cells.
  std::vector<Delaunay::Cell_handle> tet;
  tet.reserve(7 * n);
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    c->info() = static_cast<Index>(tet.size());
    tet.push_back(c);
  }
  const std::size_t nt = tet.size();
  std::vector<std::array<Index, 4>> tv(nt), tn(nt);
  std::vector<std::uint8_t> finite(nt);
  std::vector<Index> inc_start(n + 1, 0);
  for (std::size_t t = 0; t < nt; ++t) {
    finite[t] = !dt.is_infinite(tet[t]);
    for (int k = 0; k < 4; ++k) {
      const auto v = tet[t]->vertex(k);
      tv[t][k] = dt.is_infinite(v) ? kInvalidIndex : v->info();
      tn[t][k] = tet[t]->neighbor(k)->info();
      if (tv[t][k] != kInvalidIndex) ++inc_start[tv[t][k] + 1];
    }
  }
  for (std::size_t i = 0; i < n; ++i) inc_start[i + 1] += inc_start[i];
  // Seeds in CGAL's storage order (along its Hilbert sort): cells visited in
  // this order touch nearby memory one after the other.
  std::vector<Index> order;
  order.reserve(n);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) order.push_back(v->info());
  std::vector<Index> inc(inc_start[n]);
  {
    std::vector<Index> fill(inc_start.begin(), inc_start.end() - 1);
    for (std::size_t t = 0; t < nt; ++t)
      for (Index v : tv[t])
        if (v != kInvalidIndex) inc[fill[v]++] = static_cast<Index>(t);
  }
  const double margin = kInteriorMargin * domain.scale;
  auto inside = [&](const Vec3& p) {
    if (domain.is_box)
      return (p.array() > domain.lo.array() + margin).all() && (p.array() < domain.hi.array() - margin).all();
    if ((p - domain.center).norm() < domain.inner_radius - margin) return true;
    return domain.excess(p) < -margin;
  };
  std::vector<Vec3> cc(nt, Vec3::Zero());
  std::vector<std::uint8_t> cc_inside(nt, 0);  // finite and inside the domain by the margin
  const std::int64_t nts = static_cast<std::int64_t>(nt);
#pragma omp parallel for schedule(static)
  for (std::int64_t t = 0; t < nts; ++t) {
    if (!finite[t]) continue;
    std::array<Index, 4> g = tv[t];
    std::sort(g.begin(), g.end());
    cc[t] = planesPoint(g, {}, seeds, domain);
    cc_inside[t] = inside(cc[t]);
  }
  // One Voronoi vertex per group of adjacent cells with (nearly) equal
  // circumcentres; the group's id is its lowest cell.
  const double weld = kWeldTolerance * domain.scale;
  std::vector<Index> group(nt);
  for (std::size_t t = 0; t < nt; ++t) group[t] = static_cast<Index>(t);
  auto root = [&](Index t) {
    while (group[t] != t) t = group[t] = group[group[t]];
    return t;
  };
  for (std::size_t t = 0; t < nt; ++t) {
    if (!finite[t]) continue;
    for (Index u : tn[t]) {
      if (u < t || !finite[u] || (cc[t] - cc[u]).squaredNorm() > weld * weld) continue;
      const Index a = root(static_cast<Index>(t)), b = root(u);
      group[std::max(a, b)] = std::min(a, b);
    }
  }
  for (std::size_t t = 0; t < nt; ++t) group[t] = root(static_cast<Index>(t));

  const double on = kOnTolerance * domain.scale;
  const bool complex = output == CellOutput::Complex;
  // The ball starts from a box a little larger than its bounding box, so that
  // the icosphere's faces cut every box face away.
  const Vec3 margin_box = domain.is_box ? Vec3::Zero() : Vec3::Constant(0.01 * domain.scale);
  const std::array<int, 6> box_labels =
      domain.is_box ? std::array<int, 6>{-1, -2, -3, -4, -5, -6}
                    : std::array<int, 6>{kScaffoldLabel, kScaffoldLabel, kScaffoldLabel,
                                         kScaffoldLabel, kScaffoldLabel, kScaffoldLabel};

  ClippedCells3 out;
  out.centroids.resize(n);
  std::vector<CellWalls> walls(complex ? n : 0);
  // Boundary cells: clipped vertices (canonical positions) per wall, welded later.
  std::vector<std::vector<Vec3>> clipped_points(complex ? n : 0);
  std::vector<std::uint8_t> is_boundary(n, 0);
  std::vector<std::string> errors(n);
  std::vector<Index> duplicate(n, kInvalidIndex);  // a neighbour closer than duplicate_distance
  const double d2 = std::pow(duplicate_tolerance * domain.scale, 2);
  const std::int64_t ns = static_cast<std::int64_t>(n);
#pragma omp parallel
  {
    ClipPolytope cell;
    std::vector<Index> nbrs, loop;
    CellWalls local;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t q = 0; q < ns; ++q) {
      const Index i = order[q];
      const Vec3& s = seeds[i];
      bool interior = true;
      nbrs.clear();
      for (Index k = inc_start[i]; k < inc_start[i + 1]; ++k) {
        const Index t = inc[k];
        if (!cc_inside[t]) interior = false;
        for (Index v : tv[t])
          if (v != kInvalidIndex && v != i) nbrs.push_back(v);
      }
      std::sort(nbrs.begin(), nbrs.end());
      nbrs.erase(std::unique(nbrs.begin(), nbrs.end()), nbrs.end());
      for (Index j : nbrs)
        if ((seeds[j] - s).squaredNorm() < d2 && duplicate[i] == kInvalidIndex) duplicate[i] = j;
      if (interior) {
        local = CellWalls{};
        double v6 = 0;
        Vec3 moment = Vec3::Zero();
        for (Index j : nbrs) {
          // A cell t0 around edge ij, then around the edge counter-clockwise
          // seen from j (so the wall's normal points from i to j).
          Index t0 = kInvalidIndex;
          for (Index k = inc_start[i]; k < inc_start[i + 1] && t0 == kInvalidIndex; ++k)
            for (Index v : tv[inc[k]])
              if (v == j) t0 = inc[k];
          std::array<Index, 2> ab{};
          int m = 0;
          for (Index v : tv[t0])
            if (v != i && v != j) ab[m++] = v;
          auto p = [&](Index v) { return Point(seeds[v].x(), seeds[v].y(), seeds[v].z()); };
          // Stepping out of t0 through the facet opposite a turns from a towards b.
          Index a = ab[0];
          if (CGAL::orientation(p(i), p(j), p(ab[0]), p(ab[1])) != CGAL::POSITIVE) a = ab[1];
          loop.clear();
          Index t = t0;
          do {
            const Index g = group[t];
            if (loop.empty() || loop.back() != g) loop.push_back(g);
            int ka = 0;
            while (tv[t][ka] != a) ++ka;
            Index next_b = kInvalidIndex;
            for (Index v : tv[t])
              if (v != i && v != j && v != a) next_b = v;
            t = tn[t][ka];
            a = next_b;
          } while (t != t0);
          const std::size_t before = local.labels.size();
          local.add(static_cast<int>(j), loop);
          if (local.labels.size() == before) continue;
          const Index* w = local.keys.data() + local.starts[before];
          const std::size_t wm = local.starts[before + 1] - local.starts[before];
          const Vec3 q0 = cc[w[0]] - s;
          for (std::size_t k = 1; k + 1 < wm; ++k) {
            const Vec3 q1 = cc[w[k]] - s, q2 = cc[w[k + 1]] - s;
            const double d = q0.dot(q1.cross(q2));
            v6 += d;
            moment += d * (q0 + q1 + q2) / 4;
          }
        }
        if (local.labels.size() < 4 || !(v6 > 0)) {
          errors[i] = "the Voronoi cell of " + describeSeed(i, s) + " has no volume";
          continue;
        }
        out.centroids[i] = s + moment / v6;
        if (complex) walls[i] = std::move(local);
        continue;
      }
      is_boundary[i] = 1;
      cell.resetToBox(domain.lo - margin_box, domain.hi + margin_box, box_labels);
      // Nearest first: the cell shrinks early, so later planes cut less or nothing.
      std::sort(nbrs.begin(), nbrs.end(), [&](Index x, Index y) {
        return std::make_pair((seeds[x] - s).squaredNorm(), x) < std::make_pair((seeds[y] - s).squaredNorm(), y);
      });
      try {
        for (Index v : nbrs) {
          const Vec3& t = seeds[v];
          const Vec3 normal = (t - s).normalized();
          cell.clip(normal, normal.dot((s + t) / 2), static_cast<int>(v), on);
        }
        if (!domain.is_box) {
          const double reach = cell.reach(s);
          if ((s - domain.center).norm() + reach >= domain.inner_radius) {
            for (std::size_t k = 0; k < domain.faces.size(); ++k) {
              const HalfSpace& hs = domain.faces[k];
              if (hs.offset - hs.normal.dot(s) < reach + on)
                cell.clip(hs.normal, hs.offset, domainLabel(k), on);
            }
          }
        }
      } catch (const GeometryError& e) {
        errors[i] = "the Voronoi cell of " + describeSeed(i, s) + ": " + e.what();
        continue;
      }
      if (cell.numFaces() < 4) {
        errors[i] = "the Voronoi cell of " + describeSeed(i, s) + " vanished when clipped to the domain";
        continue;
      }
      double volume = 0;
      cell.volumeAndCentroid(volume, out.centroids[i]);
      if (!complex) continue;
      // Walls with local vertex numbers now; welded (sequentially) below.
      CellWalls& cw = walls[i];
      std::vector<Vec3>& pts = clipped_points[i];
      for (std::size_t v = 0; v < cell.vertices().size(); ++v)
        pts.push_back(canonicalPosition(cell.vertices()[v], i, cell.vertexLabels(v), seeds, domain));
      for (std::size_t f = 0; f < cell.numFaces(); ++f) {
        if (cell.faceLabel(f) == kScaffoldLabel) {
          errors[i] = "the Voronoi cell of " + describeSeed(i, s) + " was not closed by the ball's faces";
          break;
        }
        cw.labels.push_back(cell.faceLabel(f));
        for (const int* v = cell.faceBegin(f); v != cell.faceEnd(f); ++v) cw.keys.push_back(static_cast<Index>(*v));
        cw.starts.push_back(static_cast<Index>(cw.keys.size()));
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (duplicate[i] != kInvalidIndex) throwDuplicate(seeds, i, duplicate[i]);
  for (std::size_t i = 0; i < n; ++i)
    if (!errors[i].empty()) throw GeometryError(errors[i]);
  if (!complex) return out;

  // Keys: a cell group (< nt), or nt + k for the k-th point made by clipping.
  // Clipped points weld onto the circumcentres of the boundary seeds' cells
  // first (except those on the boundary, left to the clipped points), then
  // onto each other.
  VertexWelder welder(domain.lo - margin_box, weld, 0);
  std::vector<Index> key_of_weld;
  std::vector<Vec3> extra;
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_boundary[i]) continue;
    for (Index k = inc_start[i]; k < inc_start[i + 1]; ++k) {
      const Index t = inc[k];
      if (!finite[t] || domain.excess(cc[t]) > -2 * weld) continue;  // see 2D
      const Index w = welder.weld(cc[t]);
      if (w == key_of_weld.size()) key_of_weld.push_back(group[t]);
    }
  }
  std::vector<Index> local_key, loop;
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_boundary[i]) continue;
    local_key.clear();
    for (const Vec3& p : clipped_points[i]) {
      const Index w = welder.weld(p);
      if (w == key_of_weld.size()) {
        key_of_weld.push_back(static_cast<Index>(nt + extra.size()));
        extra.push_back(p);
      }
      local_key.push_back(key_of_weld[w]);
    }
    CellWalls raw = std::move(walls[i]);
    CellWalls& cw = walls[i];
    cw = CellWalls{};
    for (std::size_t f = 0; f < raw.labels.size(); ++f) {
      loop.clear();
      for (Index k = raw.starts[f]; k < raw.starts[f + 1]; ++k) {
        const Index g = local_key[raw.keys[k]];
        if (loop.empty() || loop.back() != g) loop.push_back(g);
      }
      cw.add(raw.labels[f], loop);
    }
    clipped_points[i] = {};
  }

  // Assemble: a wall between cells i < j is stored once from i (normal
  // towards j) and used reversed by j; vertices numbered by first use.
  std::vector<Index> id(nt + extra.size(), kInvalidIndex);
  std::vector<std::vector<std::pair<Index, Index>>> shared(n);  // (j, face) made by i < j
  std::vector<std::uint8_t> matched;
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
        Index face = kInvalidIndex;
        for (const auto& [j, fid] : shared[other])
          if (j == i) face = fid;
        bool same = face != kInvalidIndex;
        if (same) {
          // Compare in vertex ids: every key of the stored wall has one.
          loop.clear();
          for (Index k : keys) loop.push_back(id[k]);
          const std::span<const Index> stored(out.face_loops.data() + out.face_offsets[face],
                                              out.face_offsets[face + 1] - out.face_offsets[face]);
          same = reverseOf(stored, loop);
        }
        if (!same)
          throw GeometryError("the wall between the Voronoi cells of " + describeSeed(other, seeds[other]) +
                              " and " + describeSeed(i, seeds[i]) +
                              " comes out differently from the two cells (nearly degenerate seeds)");
        matched[face] = 1;
        out.cell_faces.push_back({face, true});
        continue;
      }
      const Index face = static_cast<Index>(out.face_offsets.size() - 1);
      for (Index k : keys) {
        if (id[k] == kInvalidIndex) {
          id[k] = static_cast<Index>(out.positions.size());
          out.positions.push_back(k < nt ? cc[k] : extra[k - nt]);
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
