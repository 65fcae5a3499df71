// Curved-sheet tissues (Embedding::Surface): each cell is meshed on its fan
// surface — the triangles from the vertex mean to each loop edge that the
// tissue's geometry measures — so mesh areas equal cell areas exactly, also
// for non-planar cells.
//
// Every fan triangle is planar: it is meshed in its own plane by a CGAL
// constrained Delaunay refinement whose boundary points are those of its
// three sides. Sides are segments shared between fan triangles: a wall edge
// (shared by the two cells of the wall) or a spoke (centre to vertex, shared
// by two fan triangles of one cell). Each segment is subdivided once, in 3D,
// and every triangle using it gets exactly the same points, so the mesh
// conforms across walls and spokes. When the refinement of one triangle
// splits a side (to respect the angle bound), that point is added to the
// shared segment and the triangles on the other side are remeshed; the
// rounds repeat until no side changes (at most kMaxRounds).
//
// Sharp fan triangles — a fan angle below the angle bound, e.g. the sliver
// from the centre to a short wall edge — cannot meet the bound, and Delaunay
// refinement of a wedge of angle theta puts O(1/theta) points on its sides
// (edges must get as short as the wedge is wide). Through the shared spokes
// those points spread to the neighbouring triangles, round after round: a
// 1e-4 rad sliver on a dome tissue made tens of thousands of side points and
// never finished. Sharp triangles are therefore refined inside only (their
// sides keep the points the uniform subdivision and the neighbours give
// them), and every refinement runs within a vertex budget
// (bounded_refinement.hpp) that raises a GeometryError naming the cell.

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "bounded_refinement.hpp"
#include "polygon_fan.hpp"
#include "tessella/mesh/geometry_check.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/errors.hpp"
#include "triangle_criteria.hpp"
#include "wall_segments.hpp"

namespace tessella {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct PointTag {
  int corner = -1;     // 0 centre, 1 and 2 the loop vertices; -1 otherwise
  int segment = -1;    // the shared segment a side point lies on
  double param = -1;   // its parameter along that segment
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<PointTag, K, CGAL::Delaunay_mesh_vertex_base_2<K>>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;
/// Refines inside a triangle only, never splitting its sides: the last resort
/// when side splits keep bouncing between neighbouring fan triangles.
using InteriorMesher = CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, Criteria>;

/// A segment shared by fan triangles: a wall edge or a spoke.
struct Segment {
  int node_a = -1, node_b = -1;  // corner nodes
  Vec3 a, b;
  std::vector<double> params;     // sorted, in (0, 1)
  std::vector<int> triangles;     // fan triangles using it
};

/// Fan triangle (centre, loop vertex i, loop vertex i+1) of a cell.
struct FanTriangle {
  int cell = -1;
  std::array<int, 3> corner_nodes{};
  std::array<Vec3, 3> corners;
  std::array<int, 3> side_segment{};      // sides: 0 centre->vi, 1 vi->vi+1, 2 vi+1->centre
  std::array<bool, 3> side_reversed{};    // traversed from the segment's b to a
  Vec3 u, v;                              // orthonormal in-plane frame at corners[0]
  int loop_position = 0;                  // i: the triangle (centre, v_i, v_i+1)
  double min_angle_degrees = 0;           // its smallest angle
  bool sharp = false;                     // min angle below the bound: refined inside only
};

double smallestAngleDegrees(const std::array<Vec3, 3>& c) {
  double smallest = 180.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3 a = c[(k + 1) % 3] - c[k], b = c[(k + 2) % 3] - c[k];
    smallest = std::min(smallest, std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / std::numbers::pi);
  }
  return smallest;
}

struct LocalMesh {
  std::vector<PointTag> tags;
  std::vector<Vec3> positions;  // 3D
  std::vector<std::array<int, 3>> triangles;
};

K::Point_2 local(const FanTriangle& f, const Vec3& p) { return {(p - f.corners[0]).dot(f.u), (p - f.corners[0]).dot(f.v)}; }

/// Meshes one fan triangle in its plane; appends (segment, param) for every
/// point the refinement put on a side.
template <typename RefineMesher>
LocalMesh meshFanTriangle(const FanTriangle& f, const std::vector<Segment>& segments, double shape_bound,
                          double max_edge, std::vector<std::pair<int, double>>& new_side_points) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> boundary;
  for (int s = 0; s < 3; ++s) {
    auto h = cdt.insert(local(f, f.corners[static_cast<std::size_t>(s)]));
    h->info().corner = s;
    boundary.push_back(h);
    const Segment& seg = segments[static_cast<std::size_t>(f.side_segment[static_cast<std::size_t>(s)])];
    const bool rev = f.side_reversed[static_cast<std::size_t>(s)];
    const std::size_t n = seg.params.size();
    for (std::size_t k = 0; k < n; ++k) {
      const double t = seg.params[rev ? n - 1 - k : k];
      auto hp = cdt.insert(local(f, seg.a + t * (seg.b - seg.a)));
      hp->info().segment = f.side_segment[static_cast<std::size_t>(s)];
      hp->info().param = t;
      boundary.push_back(hp);
    }
  }
  for (std::size_t i = 0; i < boundary.size(); ++i) cdt.insert_constraint(boundary[i], boundary[(i + 1) % boundary.size()]);
  if (shape_bound > 0.0 || max_edge > 0.0) {
    double min_spacing = std::numeric_limits<double>::infinity(), extent = 0;
    for (std::size_t i = 0; i < boundary.size(); ++i) {
      const auto d = boundary[(i + 1) % boundary.size()]->point() - boundary[i]->point();
      min_spacing = std::min(min_spacing, std::sqrt(d.squared_length()));
      extent = std::max(extent, std::sqrt(d.squared_length()));
    }
    extent = std::max({extent, (f.corners[1] - f.corners[0]).norm(), (f.corners[2] - f.corners[0]).norm(),
                       (f.corners[2] - f.corners[1]).norm()});
    const double area = 0.5 * (f.corners[1] - f.corners[0]).cross(f.corners[2] - f.corners[0]).norm();
    const std::size_t budget = mesh_detail::refinementBudget(boundary.size(), area, extent, min_spacing, max_edge);
    RefineMesher mesher(cdt, Criteria(shape_bound, max_edge));
    // Domain: everything inside the constrained boundary.
    mesh_detail::refineWithinBudget(mesher, cdt, budget, [&](std::size_t vertices) {
      throw GeometryError("surface mesher: refining cell " + std::to_string(f.cell) + " (fan triangle " +
                              std::to_string(f.loop_position) + ", smallest angle " +
                              std::to_string(f.min_angle_degrees) + " degrees, " + std::to_string(boundary.size()) +
                              " boundary points) did not finish within " + std::to_string(vertices) +
                              " vertices; lower min_angle_degrees or check the cell's geometry",
                          ElementId{2, static_cast<Index>(f.cell)});
    });
  } else {
    Mesher::mark_facets(cdt, static_cast<K::Point_2*>(nullptr), static_cast<K::Point_2*>(nullptr));
  }

  LocalMesh out;
  std::map<Cdt::Vertex_handle, int> index;
  const auto nodeOf = [&](Cdt::Vertex_handle h) {
    auto [it, inserted] = index.emplace(h, static_cast<int>(out.tags.size()));
    if (inserted) {
      PointTag tag = h->info();
      Vec3 p = f.corners[0] + h->point().x() * f.u + h->point().y() * f.v;
      if (tag.corner < 0 && tag.segment < 0) {
        // A Steiner point: on a side if a constrained edge leaves it.
        auto e = cdt.incident_edges(h), done = e;
        bool on_side = false;
        do on_side = on_side || cdt.is_constrained(*e);
        while (++e != done);
        if (on_side) {
          // Which side: the one the point is closest to, in 2D.
          int best = 0;
          double best_d = std::numeric_limits<double>::infinity(), best_t = 0;
          for (int s = 0; s < 3; ++s) {
            const Vec3 a = f.corners[static_cast<std::size_t>(s)], b = f.corners[static_cast<std::size_t>((s + 1) % 3)];
            const Vec3 d = b - a;
            const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
            const double dist = (a + t * d - p).norm();
            if (dist < best_d) best = s, best_d = dist, best_t = t;
          }
          const auto side = static_cast<std::size_t>(best);
          tag.segment = f.side_segment[side];
          tag.param = f.side_reversed[side] ? 1.0 - best_t : best_t;
          new_side_points.emplace_back(tag.segment, tag.param);
          const Segment& seg = segments[static_cast<std::size_t>(tag.segment)];
          p = seg.a + tag.param * (seg.b - seg.a);
        }
      }
      out.tags.push_back(tag);
      out.positions.push_back(p);
    }
    return it->second;
  };
  for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh)
    if (fh->is_in_domain()) out.triangles.push_back({nodeOf(fh->vertex(0)), nodeOf(fh->vertex(1)), nodeOf(fh->vertex(2))});
  return out;
}

void insertParam(std::vector<double>& params, double t) {
  const auto it = std::lower_bound(params.begin(), params.end(), t);
  const double tol = 1e-12;
  if ((it != params.end() && *it - t < tol) || (it != params.begin() && t - *(it - 1) < tol)) return;
  if (t <= tol || t >= 1.0 - tol) return;
  params.insert(it, t);
}

void uniformParams(Segment& s, double max_edge) {
  const double length = (s.b - s.a).norm();
  const int pieces = max_edge > 0 ? std::max(1, static_cast<int>(std::ceil(length / max_edge - 1e-9))) : 1;
  for (int k = 1; k < pieces; ++k) s.params.push_back(static_cast<double>(k) / pieces);
}

}  // namespace

FeMesh meshSurfaceTissue(const Tissue& t, const MeshOptions& options) {
  validateMeshOptions(options);
  if (t.dim() != 2 || t.embedding() != Embedding::Surface)
    throw InputError(std::string("meshSurfaceTissue needs a curved-sheet (surface) 2D tissue, got a ") +
                     embeddingName(t.embedding()) + " tissue of dimension " + std::to_string(t.dim()));
  checkMeshable(t, options);
  const auto& topo = t.topology();
  const double max_edge = options.max_edge_length;
  const double shape_bound = mesh_detail::shapeBound(options.min_angle_degrees);

  // Corner nodes: live vertices, then one centre per cell.
  std::vector<Vec3> node_pos;
  std::vector<int> node_vertex;
  std::vector<int> vertex_node(t.slots(0), -1);
  for (VertexId v : t.vertices()) {
    vertex_node[v.index()] = static_cast<int>(node_pos.size());
    node_pos.push_back(t.position(v));
    node_vertex.push_back(static_cast<int>(v.index()));
  }
  // Segments: every wall edge, then the spokes of every cell.
  std::vector<Segment> segments(t.slots(1));
  for (EdgeId e : t.edges()) {
    Segment& s = segments[e.index()];
    s.node_a = vertex_node[topo.edgeFrom(e).index()];
    s.node_b = vertex_node[topo.edgeTo(e).index()];
    s.a = t.position(topo.edgeFrom(e));
    s.b = t.position(topo.edgeTo(e));
    uniformParams(s, max_edge);
  }
  std::vector<FanTriangle> fans;
  for (CellId c : t.cells()) {
    const FaceId face = t.cellFace(c);
    const auto verts = topo.faceVertices(face);
    const auto edges = topo.faceEdges(face);
    const auto loop = mesh_detail::loopPositions(t, face);
    const int centre = static_cast<int>(node_pos.size());
    node_pos.push_back(mesh_detail::loopMean(loop));
    node_vertex.push_back(-1);
    const int first_spoke = static_cast<int>(segments.size());
    for (VertexId v : verts) {
      Segment s;
      s.node_a = centre;
      s.node_b = vertex_node[v.index()];
      s.a = node_pos[static_cast<std::size_t>(centre)];
      s.b = t.position(v);
      uniformParams(s, max_edge);
      segments.push_back(std::move(s));
    }
    const int n = static_cast<int>(verts.size());
    for (int i = 0; i < n; ++i) {
      FanTriangle f;
      f.cell = static_cast<int>(c.index());
      const int j = (i + 1) % n;
      f.corner_nodes = {centre, vertex_node[verts[static_cast<std::size_t>(i)].index()], vertex_node[verts[static_cast<std::size_t>(j)].index()]};
      for (int k = 0; k < 3; ++k) f.corners[static_cast<std::size_t>(k)] = node_pos[static_cast<std::size_t>(f.corner_nodes[static_cast<std::size_t>(k)])];
      const OrientedEdge oe = edges[static_cast<std::size_t>(i)];
      f.side_segment = {first_spoke + i, static_cast<int>(oe.handle().index()), first_spoke + j};
      f.side_reversed = {false, oe.reversed(), true};
      const Vec3 normal = (f.corners[1] - f.corners[0]).cross(f.corners[2] - f.corners[0]).normalized();
      f.u = (f.corners[1] - f.corners[0]).normalized();
      f.v = normal.cross(f.u);
      f.loop_position = i;
      f.min_angle_degrees = smallestAngleDegrees(f.corners);
      f.sharp = options.min_angle_degrees > 0.0 && f.min_angle_degrees < options.min_angle_degrees;
      if (!f.u.allFinite() || !f.v.allFinite())
        throw GeometryError("surface mesher: cell " + std::to_string(c.index()) + " has a degenerate fan triangle at loop position " +
                                std::to_string(i),
                            ElementId{2, c.index()});
      const int id = static_cast<int>(fans.size());
      for (int s : f.side_segment) segments[static_cast<std::size_t>(s)].triangles.push_back(id);
      fans.push_back(f);
    }
  }

  // Refine every fan triangle; feed side splits back to the shared segments
  // until no triangle splits a side.
  std::vector<LocalMesh> local(fans.size());
  std::vector<int> dirty(fans.size());
  for (std::size_t i = 0; i < fans.size(); ++i) dirty[i] = static_cast<int>(i);
  // Side splits normally settle in a round or two. Near very sharp corners
  // they can bounce between neighbouring triangles (each side of a sharp
  // wedge refines the other), with side points multiplying each round. So
  // after kMaxRounds, or as soon as a later round adds more side points than
  // there were, the remaining triangles are refined inside only, keeping
  // their shared side points: the mesh stays conforming and exact, and the
  // angle bound may be missed next to those sides.
  constexpr int kMaxRounds = 8;
  std::size_t side_points = 0;
  for (const Segment& s : segments) side_points += s.params.size();
  bool bouncing = false;
  for (int round = 0; !dirty.empty(); ++round) {
    std::vector<std::pair<int, double>> splits;
    if (round == kMaxRounds || bouncing) {
      for (int i : dirty)
        local[static_cast<std::size_t>(i)] =
            meshFanTriangle<InteriorMesher>(fans[static_cast<std::size_t>(i)], segments, shape_bound, max_edge, splits);
      break;
    }
    for (int i : dirty) {
      const FanTriangle& f = fans[static_cast<std::size_t>(i)];
      local[static_cast<std::size_t>(i)] =
          f.sharp ? meshFanTriangle<InteriorMesher>(f, segments, shape_bound, max_edge, splits)
                  : meshFanTriangle<Mesher>(f, segments, shape_bound, max_edge, splits);
    }
    std::vector<char> mark(fans.size(), 0);
    for (const auto& [seg, param] : splits) {
      Segment& s = segments[static_cast<std::size_t>(seg)];
      const std::size_t before = s.params.size();
      insertParam(s.params, param);
      if (s.params.size() != before)
        for (int tri : s.triangles) mark[static_cast<std::size_t>(tri)] = 1;
    }
    std::size_t added = 0;
    for (const Segment& s : segments) added += s.params.size();
    added -= side_points;
    bouncing = round >= 1 && added > std::max<std::size_t>(side_points, 64);
    side_points += added;
    // A triangle that split its own side must be remeshed too, so its side
    // points are the segment's (bit-identical) points.
    dirty.clear();
    for (std::size_t i = 0; i < fans.size(); ++i)
      if (mark[i]) dirty.push_back(static_cast<int>(i));
  }

  // Assemble: side points are keyed by (segment, param), shared by every triangle.
  std::map<std::pair<int, double>, int> side_node;
  for (std::size_t s = 0; s < segments.size(); ++s)
    for (double tparam : segments[s].params) {
      side_node[{static_cast<int>(s), tparam}] = static_cast<int>(node_pos.size());
      node_pos.push_back(segments[s].a + tparam * (segments[s].b - segments[s].a));
      node_vertex.push_back(-1);
    }
  std::vector<std::array<int, 4>> elements;
  for (std::size_t i = 0; i < fans.size(); ++i) {
    const LocalMesh& lm = local[i];
    std::vector<int> node(lm.tags.size());
    for (std::size_t k = 0; k < lm.tags.size(); ++k) {
      const PointTag& tag = lm.tags[k];
      if (tag.corner >= 0) {
        node[k] = fans[i].corner_nodes[static_cast<std::size_t>(tag.corner)];
      } else if (tag.segment >= 0) {
        const auto it = side_node.find({tag.segment, tag.param});
        if (it == side_node.end())
          throw GeometryError("surface mesher: a side point of cell " + std::to_string(fans[i].cell) +
                                  " is missing from its shared segment (internal error)",
                              ElementId{2, static_cast<Index>(fans[i].cell)});
        node[k] = it->second;
      } else {
        node[k] = static_cast<int>(node_pos.size());
        node_pos.push_back(lm.positions[k]);
        node_vertex.push_back(-1);
      }
    }
    for (const auto& tri : lm.triangles)
      elements.push_back({node[static_cast<std::size_t>(tri[0])], node[static_cast<std::size_t>(tri[1])],
                          node[static_cast<std::size_t>(tri[2])], fans[i].cell});
  }

  FeMesh mesh;
  mesh.dim = 2;
  mesh.nodes.resize(static_cast<Eigen::Index>(node_pos.size()), 3);
  mesh.node_vertex.resize(static_cast<Eigen::Index>(node_pos.size()));
  for (std::size_t i = 0; i < node_pos.size(); ++i) {
    mesh.nodes.row(static_cast<Eigen::Index>(i)) = node_pos[i].transpose();
    mesh.node_vertex(static_cast<Eigen::Index>(i)) = node_vertex[i];
  }
  mesh.elements.resize(static_cast<Eigen::Index>(elements.size()), 3);
  mesh.element_cell.resize(static_cast<Eigen::Index>(elements.size()));
  for (std::size_t i = 0; i < elements.size(); ++i) {
    mesh.elements.row(static_cast<Eigen::Index>(i)) << elements[i][0], elements[i][1], elements[i][2];
    mesh.element_cell(static_cast<Eigen::Index>(i)) = elements[i][3];
  }
  std::vector<std::array<int, 3>> facets;
  std::vector<bool> boundary;
  for (EdgeId e : t.edges()) {
    const Segment& s = segments[e.index()];
    int prev = s.node_a;
    const bool on_boundary = t.isBoundaryWall(handle_cast<WallId>(e));
    for (std::size_t k = 0; k <= s.params.size(); ++k) {
      const int next = k < s.params.size() ? side_node.at({static_cast<int>(e.index()), s.params[k]}) : s.node_b;
      facets.push_back({prev, next, static_cast<int>(e.index())});
      boundary.push_back(on_boundary);
      prev = next;
    }
  }
  mesh_detail::storeWallSegments(mesh, facets, boundary);
  return mesh;
}

}  // namespace tessella
