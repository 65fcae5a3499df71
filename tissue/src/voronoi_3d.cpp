// 3D Voronoi tissues: CGAL's Delaunay tetrahedralisation gives each seed its
// neighbours; the seed's cell is the domain (a box, or the ball's bounding box
// then the icosphere's faces) cut by the bisector plane of every Delaunay
// neighbour, so walls are exactly the dual of Delaunay edges. Cell vertices
// are welded; each wall between two cells is stored once and must come out
// identical (reversed) from both cells, or a GeometryError says which.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

// CGAL headers trip -Wnull-dereference in GCC 12 optimised builds (in CGAL's
// own code); silence it for them only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#pragma GCC diagnostic pop

#include <Eigen/Dense>

#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/voronoi.hpp"
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
using CellBase = CGAL::Delaunay_triangulation_cell_base_3<Kernel>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using Point = Kernel::Point_3;

// Face labels: >= 0 a neighbour seed; -1 - k domain face k; the ball's
// bounding box faces (always cut away) get kScaffoldLabel.
constexpr int kScaffoldLabel = -1000000000;
int domainLabel(std::size_t face) { return -1 - static_cast<int>(face); }

Delaunay triangulate(std::span<const Vec3> seeds, double duplicate_distance) {
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
  const double d2 = duplicate_distance * duplicate_distance;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto va = e->first->vertex(e->second);
    const auto vb = e->first->vertex(e->third);
    if (CGAL::squared_distance(va->point(), vb->point()) < d2)
      throwDuplicate(seeds, va->info(), vb->info());
  }
  return dt;
}

// The position of a cell vertex computed from the planes through it, named
// canonically (sorted seed indices, domain faces) so that every cell sharing
// the vertex gets the same bits -- clipping interpolates along edges, which
// is ill-conditioned where a bisector grazes an edge (nearly cospherical
// seeds), and different cells would disagree by more than the weld
// tolerance. Falls back to the clipped position if the planes do not pin
// down a point near it.
Vec3 canonicalPosition(const Vec3& clipped, Index cell, std::span<const int> labels,
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
  Vec3 x;
  if (a.rows() == 3) {
    const Mat3 a3 = a;
    x = a3.partialPivLu().solve(Vec3(b));
  } else {
    x = (a.transpose() * a).ldlt().solve(a.transpose() * b);
  }
  if (!x.allFinite() || (x - clipped).norm() > 1e-7 * domain.scale) return clipped;
  if (domain.is_box)  // exactly on the box faces it lies on
    for (std::size_t k = 0; k < nf; ++k) {
      const int axis = faces[k] / 2;
      x[axis] = faces[k] % 2 ? domain.hi[axis] : domain.lo[axis];
    }
  return x;
}

// Collects the welded walls of every cell into faces/cells arrays, storing a
// wall between two cells once (from the lower-numbered cell).
class WallAssembler {
 public:
  WallAssembler(ClippedCells3& out, std::size_t cells) : out_(out) {
    out_.cells.resize(cells);
    shared_.reserve(8 * cells);
  }

  void add(std::span<const Vec3> seeds, Index cell, int label, std::vector<Index>& loop) {
    if (label < 0 || static_cast<Index>(label) > cell) {
      const Index f = static_cast<Index>(out_.faces.size());
      out_.faces.push_back(loop);
      out_.cells[cell].push_back({f, false});
      if (label >= 0) shared_.emplace(key(cell, static_cast<Index>(label)), f);
      refs_.push_back(label >= 0 ? 1 : 2);
      return;
    }
    const Index other = static_cast<Index>(label);
    auto it = shared_.find(key(other, cell));
    if (it == shared_.end() || !reverseOf(out_.faces[it->second], loop))
      throw GeometryError("the wall between the Voronoi cells of " + describeSeed(other, seeds[other]) +
                          " and " + describeSeed(cell, seeds[cell]) +
                          " comes out differently from the two cells (nearly degenerate seeds)");
    out_.cells[cell].push_back({it->second, true});
    ++refs_[it->second];
  }

  void finish(std::span<const Vec3> seeds) const {
    for (std::size_t f = 0; f < refs_.size(); ++f) {
      if (refs_[f] == 2) continue;
      for (std::size_t c = 0; c < out_.cells.size(); ++c)
        for (const CellFace& cf : out_.cells[c])
          if (cf.face == f)
            throw GeometryError("a wall of the Voronoi cell of " + describeSeed(c, seeds[c]) +
                                " is missing from its neighbour (nearly degenerate seeds)");
    }
  }

 private:
  static std::uint64_t key(Index a, Index b) { return (std::uint64_t{a} << 32) | b; }

  static bool reverseOf(const std::vector<Index>& a, const std::vector<Index>& b) {
    const std::size_t m = a.size();
    if (b.size() != m) return false;
    const auto start = std::find(b.begin(), b.end(), a[0]);
    if (start == b.end()) return false;
    const std::size_t s = static_cast<std::size_t>(start - b.begin());
    for (std::size_t k = 0; k < m; ++k)
      if (a[k] != b[(s + m - k) % m]) return false;
    return true;
  }

  ClippedCells3& out_;
  std::unordered_map<std::uint64_t, Index> shared_;
  std::vector<std::uint8_t> refs_;
};

}  // namespace

ClippedCells3 clipVoronoi3(std::span<const Vec3> seeds, const ConvexDomain3& domain,
                           double duplicate_tolerance, CellOutput output) {
  const Delaunay dt = triangulate(seeds, duplicate_tolerance * domain.scale);
  const std::size_t n = seeds.size();
  std::vector<Delaunay::Vertex_handle> handle(n);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) handle[v->info()] = v;

  const double on = kOnTolerance * domain.scale;
  const bool complex = output == CellOutput::Complex;
  // The ball starts from a box a little larger than its bounding box, so that
  // the icosphere's faces cut every box face away.
  const Vec3 margin = domain.is_box ? Vec3::Zero() : Vec3::Constant(0.01 * domain.scale);
  const std::array<int, 6> box_labels =
      domain.is_box ? std::array<int, 6>{-1, -2, -3, -4, -5, -6}
                    : std::array<int, 6>{kScaffoldLabel, kScaffoldLabel, kScaffoldLabel,
                                         kScaffoldLabel, kScaffoldLabel, kScaffoldLabel};

  ClippedCells3 out;
  out.centroids.resize(n);
  VertexWelder welder(domain.lo - margin, kWeldTolerance * domain.scale, complex ? 7 * n : 0);
  WallAssembler walls(out, complex ? n : 0);

  ClipPolytope cell;
  std::vector<Delaunay::Vertex_handle> neighbours;
  std::vector<Index> local_to_global, loop;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& s = seeds[i];
    cell.resetToBox(domain.lo - margin, domain.hi + margin, box_labels);
    neighbours.clear();
    dt.finite_adjacent_vertices(handle[i], std::back_inserter(neighbours));
    // Nearest first: the cell shrinks early, so later planes cut less or nothing.
    const Point& si = handle[i]->point();
    std::sort(neighbours.begin(), neighbours.end(), [&](const auto& a, const auto& b) {
      return std::make_pair(CGAL::squared_distance(si, a->point()), a->info()) <
             std::make_pair(CGAL::squared_distance(si, b->point()), b->info());
    });
    try {
      for (const auto& v : neighbours) {
        const Vec3 t(v->point().x(), v->point().y(), v->point().z());
        const Vec3 normal = (t - s).normalized();
        cell.clip(normal, normal.dot((s + t) / 2), static_cast<int>(v->info()), on);
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
      throw GeometryError("the Voronoi cell of " + describeSeed(i, s) + ": " + e.what());
    }
    if (cell.numFaces() < 4)
      throw GeometryError("the Voronoi cell of " + describeSeed(i, s) +
                          " vanished when clipped to the domain");
    double volume = 0;
    cell.volumeAndCentroid(volume, out.centroids[i]);
    if (!complex) continue;

    local_to_global.clear();
    for (std::size_t v = 0; v < cell.vertices().size(); ++v)
      local_to_global.push_back(welder.weld(canonicalPosition(
          cell.vertices()[v], static_cast<Index>(i), cell.vertexLabels(v), seeds, domain)));
    for (std::size_t f = 0; f < cell.numFaces(); ++f) {
      const int label = cell.faceLabel(f);
      if (label == kScaffoldLabel)
        throw GeometryError("the Voronoi cell of " + describeSeed(i, s) +
                            " was not closed by the ball's faces");
      loop.clear();
      for (const int* v = cell.faceBegin(f); v != cell.faceEnd(f); ++v) {
        const Index g = local_to_global[static_cast<std::size_t>(*v)];
        if (loop.empty() || loop.back() != g) loop.push_back(g);
      }
      while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
      if (loop.size() < 3) continue;  // a wall welded to nothing (cospherical seeds)
      walls.add(seeds, static_cast<Index>(i), label, loop);
    }
  }
  if (complex) walls.finish(seeds);
  out.positions = welder.takePositions();
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
  return buildPolyhedralTissue(cells.positions, cells.faces, cells.cells);
}

}  // namespace

Tissue voronoiTissue(std::span<const Vec3> seeds, const Box& domain, const VoronoiOptions& options) {
  return solidVoronoi(seeds, domain, options);
}

Tissue voronoiTissue(std::span<const Vec3> seeds, const Ball& domain, const VoronoiOptions& options) {
  return solidVoronoi(seeds, domain, options);
}

}  // namespace tessella
