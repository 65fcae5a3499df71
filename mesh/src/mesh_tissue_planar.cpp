// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Planar tissues: one constrained Delaunay triangulation of every vertex with
// every wall edge as a constraint (CGAL), refined for angle and size with
// Delaunay_mesher_2. Because the whole tissue is one triangulation, a Steiner
// point the refinement puts on a wall is shared by both cells by construction.
//
// Cell tagging: the face to the left of the first sub-edge of each oriented
// loop edge of a cell (loops run counter-clockwise) is seeded with the cell,
// then a flood fill spreads the tag across unconstrained edges. Done once
// before refinement (to mark the mesh domain, so holes between cells stay
// empty) and once after it (refinement replaces faces).
//
// The triangulation keeps no constraint hierarchy (CGAL's
// Constrained_triangulation_plus_2, which this mesher used before, updated a
// map of sub-constraints keyed by end points on every wall split: a third of
// the meshing time). The wall edges are handed to the mesher in the order
// that class handed them over (sorted by the xy order of their end points,
// the smaller end first), so the meshes are unchanged; after refinement each
// wall's sub-edges are found by walking its constrained edges from one end
// through the Steiner points on it.

#include "tessella/mesh/mesh_tissue.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "bounded_refinement.hpp"
#include "tessella/mesh/geometry_check.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "triangle_criteria.hpp"
#include "wall_segments.hpp"

namespace tessella::mesh {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct NodeInfo {
  int vertex = -1;  // tissue vertex, -1 for a Steiner point
  int node = -1;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<NodeInfo, K, CGAL::Delaunay_mesh_vertex_base_2<K>>;
using Fb = CGAL::Triangulation_face_base_with_info_2<int, K, CGAL::Delaunay_mesh_face_base_2<K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Base = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

/// The constrained Delaunay triangulation the mesher refines. It tells CGAL's
/// mesher (through `Constraint_hierarchy_tag`) to take the wall edges from
/// `subconstraints_begin()..end()`, a list set before refinement, instead of
/// scanning all edges; splits of wall edges need no bookkeeping here.
class Cdt : public Base {
 public:
  using Constraint_hierarchy_tag = CGAL::Tag_true;
  using Subconstraint = std::pair<std::pair<Vertex_handle, Vertex_handle>, int>;
  using Subconstraint_iterator = std::vector<Subconstraint>::const_iterator;

  Subconstraint_iterator subconstraints_begin() const { return walls_.begin(); }
  Subconstraint_iterator subconstraints_end() const { return walls_.end(); }
  void split_constraint(Vertex_handle, Vertex_handle, Vertex_handle) {}

  /// The wall edges (unsplit, before refinement), each as (smaller, larger)
  /// end in the xy order, sorted by that order of their ends: the order of
  /// Constrained_triangulation_plus_2's sub-constraint map.
  void setWalls(const std::vector<std::pair<Vertex_handle, Vertex_handle>>& walls) {
    const auto less = [this](Vertex_handle a, Vertex_handle b) {
      return compare_xy(a->point(), b->point()) == CGAL::SMALLER;
    };
    walls_.clear();
    walls_.reserve(walls.size());
    for (const auto& [a, b] : walls) walls_.push_back({less(a, b) ? std::pair(a, b) : std::pair(b, a), 0});
    std::sort(walls_.begin(), walls_.end(), [&](const Subconstraint& x, const Subconstraint& y) {
      if (less(x.first.first, y.first.first)) return true;
      return !less(y.first.first, x.first.first) && less(x.first.second, y.first.second);
    });
  }

 private:
  std::vector<Subconstraint> walls_;
};
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;

/// The vertices of the triangulation along each tissue edge, from its first
/// vertex to its second (the tissue vertices and the Steiner points between).
using WallChains = std::vector<std::vector<Cdt::Vertex_handle>>;

/// The vertices along the constrained edges from `a` to `b`: from `a`, a
/// constrained edge is followed through Steiner points (which lie on one wall
/// and have two constrained edges) to the next tissue vertex; the walk that
/// ends at `b` is the wall. The edges at `a` are tried best aligned with b - a
/// first, so the first walk is usually the wall.
std::vector<Cdt::Vertex_handle> wallChain(const Cdt& cdt, Cdt::Vertex_handle a, Cdt::Vertex_handle b, EdgeId e) {
  const auto other = [](const Cdt::Edge& edge, Cdt::Vertex_handle v) {
    const auto p = edge.first->vertex(Cdt::cw(edge.second));
    return p != v ? p : edge.first->vertex(Cdt::ccw(edge.second));
  };
  const K::Vector_2 ab = b->point() - a->point();
  std::vector<std::pair<double, Cdt::Vertex_handle>> starts;  // (-cosine to ab, next vertex)
  auto around_a = cdt.incident_edges(a);
  const auto stop_a = around_a;
  do {
    if (!around_a->first->is_constrained(around_a->second)) continue;
    const auto next = other(*around_a, a);
    const K::Vector_2 d = next->point() - a->point();
    starts.emplace_back(-(d * ab) / std::sqrt(d.squared_length()), next);
  } while (++around_a != stop_a);
  std::sort(starts.begin(), starts.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Cdt::Vertex_handle> chain;
  for (const auto& start : starts) {
    chain.assign({a, start.second});
    while (chain.back()->info().vertex < 0 && chain.size() <= cdt.number_of_vertices()) {
      const auto v = chain.back(), previous = chain[chain.size() - 2];
      Cdt::Vertex_handle next;
      int constrained = 0;
      auto around = cdt.incident_edges(v);
      const auto stop = around;
      do {
        if (!around->first->is_constrained(around->second)) continue;
        ++constrained;
        if (other(*around, v) != previous) next = other(*around, v);
      } while (++around != stop);
      if (constrained != 2 || next == Cdt::Vertex_handle())
        throw GeometryError("planar mesher: a point the refinement put on wall " + std::to_string(e.index()) +
                                " has " + std::to_string(constrained) + " wall edges instead of 2",
                            ElementId{1, e.index()});
      chain.push_back(next);
    }
    if (chain.back() == b) return chain;
  }
  throw GeometryError("planar mesher: wall " + std::to_string(e.index()) + " is missing from the triangulation",
                      ElementId{1, e.index()});
}

WallChains wallChains(const Cdt& cdt, const Tissue& t, const std::vector<Cdt::Vertex_handle>& handle) {
  WallChains chains(t.slots(1));
  const auto& topo = t.topology();
  for (EdgeId e : t.edges())
    chains[e.index()] = wallChain(cdt, handle[topo.edgeFrom(e).index()], handle[topo.edgeTo(e).index()], e);
  return chains;
}

/// Tags every face with the cell containing it (-1 outside all cells).
void tagCells(Cdt& cdt, const Tissue& t, const WallChains& chains) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  const auto& topo = t.topology();
  std::queue<Cdt::Face_handle> queue;
  for (CellId c : t.cells()) {
    const int cell = static_cast<int>(c.index());
    for (OrientedEdge oe : topo.faceEdges(t.cellFace(c))) {
      // First sub-edge of the wall in the loop's direction.
      const auto& chain = chains[oe.handle().index()];
      const std::size_t last = chain.size() - 1;
      const Cdt::Vertex_handle a = oe.reversed() ? chain[last] : chain[0];
      const Cdt::Vertex_handle b = oe.reversed() ? chain[last - 1] : chain[1];
      Cdt::Face_handle f;
      int opposite = 0;
      if (!cdt.is_edge(a, b, f, opposite))
        throw GeometryError("planar mesher: wall " + std::to_string(oe.handle().index()) +
                                " of cell " + std::to_string(cell) + " is missing from the triangulation",
                            ElementId{1, oe.handle().index()});
      if (f->vertex(f->ccw(opposite)) != a) f = f->neighbor(opposite);  // the face left of a -> b
      if (cdt.is_infinite(f))
        throw GeometryError("planar mesher: cell " + std::to_string(cell) + " lies outside its own wall " +
                                std::to_string(oe.handle().index()) + " (clockwise loop)",
                            ElementId{2, c.index()});
      if (f->info() == cell) continue;
      if (f->info() != -1)
        throw GeometryError("planar mesher: cells " + std::to_string(f->info()) + " and " + std::to_string(cell) +
                                " overlap (a triangle lies in both)",
                            ElementId{2, c.index()});
      f->info() = cell;
      queue.push(f);
    }
  }
  while (!queue.empty()) {
    const auto f = queue.front();
    queue.pop();
    for (int i = 0; i < 3; ++i) {
      if (f->is_constrained(i)) continue;
      const auto g = f->neighbor(i);
      if (g->info() == f->info()) continue;
      if (g->info() != -1 || cdt.is_infinite(g))
        throw GeometryError("planar mesher: cell " + std::to_string(f->info()) +
                                " is not closed by its walls (it leaks into " +
                                (cdt.is_infinite(g) ? std::string("the outside") : "cell " + std::to_string(g->info())) +
                                ")",
                            ElementId{2, static_cast<Index>(f->info())});
      g->info() = f->info();
      queue.push(g);
    }
  }
}

}  // namespace

FeMesh meshPlanarTissue(const Tissue& t, const MeshOptions& options) {
  validateMeshOptions(options);
  if (t.dim() != 2 || t.embedding() != Embedding::Planar)
    throw InputError(std::string("meshPlanarTissue needs a planar 2D tissue, got a ") + embeddingName(t.embedding()) +
                     " tissue of dimension " + std::to_string(t.dim()));
  checkMeshable(t, options);
  checkElementLimit(t, options);

  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handle(t.slots(0));
  Cdt::Face_handle hint;
  for (VertexId v : t.vertices()) {
    const Vec3& p = t.position(v);
    handle[v.index()] = cdt.insert(K::Point_2(p.x(), p.y()), hint);
    handle[v.index()]->info().vertex = static_cast<int>(v.index());
    hint = handle[v.index()]->face();
  }
  const auto& topo = t.topology();
  WallChains chains(t.slots(1));
  std::vector<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>> walls;
  walls.reserve(t.numEdges());
  for (EdgeId e : t.edges()) {
    const auto a = handle[topo.edgeFrom(e).index()], b = handle[topo.edgeTo(e).index()];
    cdt.insert_constraint(a, b);
    chains[e.index()] = {a, b};
    walls.emplace_back(a, b);
  }
  if (cdt.number_of_vertices() != t.numVertices())
    throw GeometryError("planar mesher: walls cross (the constrained triangulation gained " +
                        std::to_string(cdt.number_of_vertices() - t.numVertices()) + " intersection vertices)");
  cdt.setWalls(walls);

  tagCells(cdt, t, chains);
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(f->info() >= 0);
  const double angle_bound = detail::shapeBound(options.min_angle_degrees);
  if (angle_bound > 0.0 || options.max_edge_length > 0.0) {
    double shortest = std::numeric_limits<double>::infinity();
    for (EdgeId e : t.edges()) shortest = std::min(shortest, (t.position(topo.edgeTo(e)) - t.position(topo.edgeFrom(e))).norm());
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (VertexId v : t.vertices()) lo = lo.cwiseMin(t.position(v)), hi = hi.cwiseMax(t.position(v));
    const std::size_t budget =
        detail::refinementBudget(t.numVertices(), totalMeasure(t), (hi - lo).norm(), shortest, options.max_edge_length);
    Mesher mesher(cdt, Criteria(angle_bound, options.max_edge_length));
    // The domain is the tagged faces.
    detail::refineWithinBudget(
        mesher, cdt, budget,
        [&](std::size_t vertices) {
          throw GeometryError("planar mesher: refinement did not finish within " + std::to_string(vertices) +
                              " vertices (" + std::to_string(t.numVertices()) + " tissue vertices, shortest wall " +
                              formatNumber(shortest, 6) + ", min_angle_degrees " +
                              formatNumber(options.min_angle_degrees) + "); lower min_angle_degrees");
        },
        true);
    chains = wallChains(cdt, t, handle);
    tagCells(cdt, t, chains);
  }

  FeMesh mesh;
  mesh.dim = 2;
  int nodes = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) v->info().node = nodes++;
  mesh.nodes.resize(nodes, 3);
  mesh.node_vertex.resize(nodes);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    const int n = v->info().node;
    mesh.nodes.row(n) << v->point().x(), v->point().y(), 0.0;
    mesh.node_vertex(n) = v->info().vertex;
  }
  std::vector<std::array<int, 4>> elements;  // 3 nodes + cell
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() >= 0)
      elements.push_back({f->vertex(0)->info().node, f->vertex(1)->info().node, f->vertex(2)->info().node, f->info()});
  mesh.elements.resize(static_cast<Eigen::Index>(elements.size()), 3);
  mesh.element_cell.resize(static_cast<Eigen::Index>(elements.size()));
  for (std::size_t i = 0; i < elements.size(); ++i) {
    mesh.elements.row(static_cast<Eigen::Index>(i)) << elements[i][0], elements[i][1], elements[i][2];
    mesh.element_cell(static_cast<Eigen::Index>(i)) = elements[i][3];
  }

  std::vector<std::array<int, 3>> facets;  // 2 nodes + wall
  std::vector<bool> boundary;
  for (EdgeId e : t.edges()) {
    const bool on_boundary = t.isBoundaryWall(handle_cast<WallId>(e));
    const auto& chain = chains[e.index()];
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      facets.push_back({chain[i]->info().node, chain[i + 1]->info().node, static_cast<int>(e.index())});
      boundary.push_back(on_boundary);
    }
  }
  detail::storeWallSegments(mesh, facets, boundary);
  return mesh;
}

}  // namespace tessella::mesh
