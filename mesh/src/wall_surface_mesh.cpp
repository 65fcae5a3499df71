#include "wall_surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "bounded_refinement.hpp"
#include "tessella/tissue/errors.hpp"
#include "triangle_criteria.hpp"

namespace tessella::mesh_detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
/// Which boundary point of its piece a vertex is; -1 for points the
/// refinement added (CGAL default-constructs their info).
struct BoundaryTag {
  int index = -1;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<BoundaryTag, K, CGAL::Delaunay_mesh_vertex_base_2<K>>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;
/// Refines inside a piece only, never splitting its sides: the last round.
using InteriorMesher = CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, Criteria>;

/// A side shared by pieces: a tissue edge (shared by every wall around it) or
/// a spoke of a non-planar wall's fan. Runs from the smaller point id `a` to
/// `b`; its points are at parameters `params` (sorted, in (0, 1)).
struct Side {
  int a = -1, b = -1;
  Vec3 pa, pb;
  std::vector<double> params;
  std::vector<int> pieces;
  Vec3 at(double t) const { return pa + t * (pb - pa); }
};

/// A planar piece of a wall: the wall's polygon, or one fan triangle of a
/// non-planar wall. Corners are WallTriangulation point ids, counter-clockwise
/// about `normal`; side i runs from corner i to corner i + 1.
struct Piece {
  int wall = -1;
  std::vector<int> corners;
  std::vector<int> sides;
  Vec3 normal;
};

/// A boundary point of a piece: corner `corner`, or point k of side `side`.
struct BoundaryPoint {
  Vec3 position;
  int corner = -1;
  int side = -1, k = -1;
};

/// A piece meshed in its plane: triangles over its boundary points
/// (index >= 0) and its own added interior points (-(k + 1)).
struct PieceMesh {
  std::vector<Vec3> added;
  std::vector<std::array<int, 3>> triangles;
};

std::uint64_t sideKey(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

std::vector<BoundaryPoint> pieceBoundary(const Piece& p, const std::vector<Side>& sides,
                                         const std::vector<Vec3>& points) {
  std::vector<BoundaryPoint> out;
  const std::size_t n = p.corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back({points[static_cast<std::size_t>(p.corners[i])], p.corners[i], -1, -1});
    const Side& s = sides[static_cast<std::size_t>(p.sides[i])];
    const std::size_t m = s.params.size();
    const bool forward = s.a == p.corners[i];
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t k = forward ? j : m - 1 - j;
      out.push_back({s.at(s.params[k]), -1, p.sides[i], static_cast<int>(k)});
    }
  }
  return out;
}

/// Meshes one piece. With `split_sides`, the refinement may split the
/// piece's sides: the parameters of those points go to `side_splits` and the
/// result is incomplete (the piece is meshed again once its sides have them).
PieceMesh meshPiece(const Piece& p, const std::vector<BoundaryPoint>& boundary, const std::vector<Side>& sides,
                    double shape_bound, double max_edge, bool split_sides,
                    std::vector<std::pair<int, double>>& side_splits) {
  const Vec3 origin = boundary[0].position;
  Vec3 u = boundary[1].position - origin;
  u = (u - u.dot(p.normal) * p.normal).normalized();
  const Vec3 v = p.normal.cross(u);
  const auto local = [&](const Vec3& x) { return K::Point_2((x - origin).dot(u), (x - origin).dot(v)); };

  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  handles.reserve(boundary.size());
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    auto h = cdt.insert(local(boundary[i].position));
    h->info().index = static_cast<int>(i);
    handles.push_back(h);
  }
  double area2 = 0, extent = 0, min_spacing = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < handles.size(); ++i) {
    const auto &a = handles[i]->point(), &b = handles[(i + 1) % handles.size()]->point();
    cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
    min_spacing = std::min(min_spacing, std::sqrt(CGAL::squared_distance(a, b)));
    extent = std::max(extent, std::sqrt(CGAL::squared_distance(a, handles[0]->point())));
    area2 += a.x() * b.y() - a.y() * b.x();
  }
  if (cdt.number_of_vertices() != boundary.size())
    throw GeometryError("wall mesher: wall " + std::to_string(p.wall) + " has coincident boundary points",
                        ElementId{2, static_cast<Index>(p.wall)});
  const std::size_t budget = refinementBudget(boundary.size(), 0.5 * std::abs(area2), 2 * extent, min_spacing, max_edge);
  const auto exceeded = [&](std::size_t vertices) {
    throw GeometryError("wall mesher: refining wall " + std::to_string(p.wall) + " did not finish within " +
                            std::to_string(vertices) + " vertices; lower min_angle_degrees or check the wall",
                        ElementId{2, static_cast<Index>(p.wall)});
  };
  if (split_sides) {
    Mesher mesher(cdt, Criteria(shape_bound, max_edge));
    refineWithinBudget(mesher, cdt, budget, exceeded);
  } else {
    InteriorMesher mesher(cdt, Criteria(shape_bound, max_edge));
    refineWithinBudget(mesher, cdt, budget, exceeded);
  }

  PieceMesh out;
  bool split = false;
  for (auto vh = cdt.finite_vertices_begin(); vh != cdt.finite_vertices_end(); ++vh) {
    if (vh->info().index >= 0) continue;
    auto e = cdt.incident_edges(vh), done = e;
    bool on_side = false;
    do on_side = on_side || cdt.is_constrained(*e);
    while (++e != done);
    const Vec3 x = origin + vh->point().x() * u + vh->point().y() * v;
    if (!on_side) {
      vh->info().index = -static_cast<int>(out.added.size()) - 1;
      out.added.push_back(x);
      continue;
    }
    // A side point: every piece on that side must get it.
    if (!split_sides)
      throw GeometryError("wall mesher: refining wall " + std::to_string(p.wall) +
                              " put a point on the wall's border (internal error)",
                          ElementId{2, static_cast<Index>(p.wall)});
    split = true;
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity(), best_t = 0;
    for (int s : p.sides) {
      const Side& side = sides[static_cast<std::size_t>(s)];
      const Vec3 d = side.pb - side.pa;
      const double t = std::clamp((x - side.pa).dot(d) / d.squaredNorm(), 0.0, 1.0);
      const double distance = (side.at(t) - x).norm();
      if (distance < best_distance) best = s, best_distance = distance, best_t = t;
    }
    side_splits.emplace_back(best, best_t);
  }
  if (split) return {};
  for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh)
    if (fh->is_in_domain())
      out.triangles.push_back({fh->vertex(0)->info().index, fh->vertex(1)->info().index, fh->vertex(2)->info().index});
  return out;
}

/// Adds parameter t to a side unless a point is already there.
bool insertParam(std::vector<double>& params, double t) {
  constexpr double tol = 1e-9;
  if (t <= tol || t >= 1.0 - tol) return false;
  const auto it = std::lower_bound(params.begin(), params.end(), t);
  if ((it != params.end() && *it - t < tol) || (it != params.begin() && t - *(it - 1) < tol)) return false;
  params.insert(it, t);
  return true;
}

}  // namespace

WallSurfaceMesh meshWallSurfaces(const Tissue& t, const WallTriangulation& walls, double max_edge,
                                 double min_angle_degrees) {
  const auto& topo = t.topology();
  // Pieces, wall by wall.
  std::vector<Piece> pieces;
  for (WallId w : t.walls()) {
    if (walls.wall_planar[w.index()]) {
      Piece p{static_cast<int>(w.index()), {}, {}, walls.wall_normal[w.index()]};
      for (VertexId v : topo.faceVertices(handle_cast<FaceId>(w))) p.corners.push_back(static_cast<int>(v.index()));
      pieces.push_back(std::move(p));
      continue;
    }
    for (const auto& tri : walls.wall_triangles[w.index()]) {
      const Vec3 &a = walls.points[static_cast<std::size_t>(tri[0])], &b = walls.points[static_cast<std::size_t>(tri[1])],
                 &c = walls.points[static_cast<std::size_t>(tri[2])];
      pieces.push_back({static_cast<int>(w.index()), {tri[0], tri[1], tri[2]}, {}, (b - a).cross(c - a).normalized()});
    }
  }

  // Sides, first subdivided uniformly to max_edge.
  std::vector<Side> sides;
  std::unordered_map<std::uint64_t, int> side_of;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    Piece& p = pieces[i];
    for (std::size_t k = 0; k < p.corners.size(); ++k) {
      const int a = p.corners[k], b = p.corners[(k + 1) % p.corners.size()];
      auto [it, inserted] = side_of.try_emplace(sideKey(a, b), static_cast<int>(sides.size()));
      if (inserted) {
        Side s;
        s.a = std::min(a, b);
        s.b = std::max(a, b);
        s.pa = walls.points[static_cast<std::size_t>(s.a)];
        s.pb = walls.points[static_cast<std::size_t>(s.b)];
        const double length = (s.pb - s.pa).norm();
        const int pieces_of_side = max_edge > 0 ? std::max(1, static_cast<int>(std::ceil(length / max_edge - 1e-9))) : 1;
        for (int j = 1; j < pieces_of_side; ++j) s.params.push_back(static_cast<double>(j) / pieces_of_side);
        sides.push_back(std::move(s));
      }
      p.sides.push_back(it->second);
      sides[static_cast<std::size_t>(it->second)].pieces.push_back(static_cast<int>(i));
    }
  }

  // Rounds: mesh the pieces whose sides changed (all, first), feed the side
  // points the refinement made back to the shared sides. Near sharp corners
  // splits can bounce between the walls around an edge, so after kMaxRounds,
  // or once a round adds more side points than there were, the pieces left
  // are refined inside only: still conforming, the angle bound may be missed
  // next to those sides (as in the surface mesher).
  const double shape_bound = min_angle_degrees > 0.0 ? shapeBound(min_angle_degrees) : 0.0;
  constexpr int kMaxRounds = 8;
  std::vector<PieceMesh> meshed(pieces.size());
  std::vector<int> dirty(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) dirty[i] = static_cast<int>(i);
  std::size_t side_points = 0;
  for (const Side& s : sides) side_points += s.params.size();
  bool last_round = shape_bound == 0.0 && max_edge == 0.0;
  for (int round = 0; !dirty.empty(); ++round) {
    last_round = last_round || round == kMaxRounds;
    std::vector<std::vector<std::pair<int, double>>> splits(dirty.size());
    std::vector<std::string> errors(dirty.size());
    std::vector<ElementId> error_elements(dirty.size());
#pragma omp parallel for schedule(dynamic, 16)
    for (std::size_t d = 0; d < dirty.size(); ++d) {
      const auto i = static_cast<std::size_t>(dirty[d]);
      try {
        meshed[i] = meshPiece(pieces[i], pieceBoundary(pieces[i], sides, walls.points), sides, shape_bound, max_edge,
                              !last_round, splits[d]);
      } catch (const GeometryError& e) {
        errors[d] = e.what();
        error_elements[d] = e.element();
      }
    }
    for (std::size_t d = 0; d < dirty.size(); ++d)
      if (!errors[d].empty()) throw GeometryError(errors[d], error_elements[d]);
    if (last_round) break;
    std::vector<char> mark(pieces.size(), 0);
    std::size_t added = 0;
    for (std::size_t d = 0; d < dirty.size(); ++d) {
      if (!splits[d].empty()) mark[static_cast<std::size_t>(dirty[d])] = 1;  // its result is incomplete
      for (const auto& [s, param] : splits[d]) {
        Side& side = sides[static_cast<std::size_t>(s)];
        if (!insertParam(side.params, param)) continue;
        ++added;
        for (int piece : side.pieces) mark[static_cast<std::size_t>(piece)] = 1;
      }
    }
    last_round = round >= 1 && added > std::max<std::size_t>(side_points, 64);
    side_points += added;
    dirty.clear();
    for (std::size_t i = 0; i < pieces.size(); ++i)
      if (mark[i]) dirty.push_back(static_cast<int>(i));
  }

  // Nodes: tissue vertices, fan centres, side points, then interior points.
  WallSurfaceMesh mesh;
  std::vector<int> point_node(walls.points.size(), -1);
  for (VertexId v : t.vertices()) {
    point_node[v.index()] = static_cast<int>(mesh.nodes.size());
    mesh.nodes.push_back(t.position(v));
    mesh.node_vertex.push_back(static_cast<int>(v.index()));
  }
  for (const Piece& p : pieces)
    for (int c : p.corners)
      if (point_node[static_cast<std::size_t>(c)] < 0) {
        point_node[static_cast<std::size_t>(c)] = static_cast<int>(mesh.nodes.size());
        mesh.nodes.push_back(walls.points[static_cast<std::size_t>(c)]);
        mesh.node_vertex.push_back(-1);
      }
  std::vector<int> side_first(sides.size());
  for (std::size_t s = 0; s < sides.size(); ++s) {
    side_first[s] = static_cast<int>(mesh.nodes.size());
    for (double param : sides[s].params) {
      mesh.nodes.push_back(sides[s].at(param));
      mesh.node_vertex.push_back(-1);
    }
  }
  mesh.wall_begin.assign(t.slots(2) + 1, 0);
  std::size_t p = 0;
  for (std::size_t w = 0; w < t.slots(2); ++w) {
    mesh.wall_begin[w] = mesh.triangles.size();
    for (; p < pieces.size() && pieces[p].wall == static_cast<int>(w); ++p) {
      const auto boundary = pieceBoundary(pieces[p], sides, walls.points);
      const int first_added = static_cast<int>(mesh.nodes.size());
      for (const Vec3& x : meshed[p].added) {
        mesh.nodes.push_back(x);
        mesh.node_vertex.push_back(-1);
      }
      for (auto tri : meshed[p].triangles) {
        for (int& n : tri) {
          if (n < 0) {
            n = first_added - n - 1;
          } else {
            const BoundaryPoint& b = boundary[static_cast<std::size_t>(n)];
            n = b.corner >= 0 ? point_node[static_cast<std::size_t>(b.corner)] : side_first[static_cast<std::size_t>(b.side)] + b.k;
          }
        }
        mesh.triangles.push_back(tri);
        mesh.triangle_wall.push_back(static_cast<int>(w));
      }
    }
  }
  mesh.wall_begin[t.slots(2)] = mesh.triangles.size();
  return mesh;
}

}  // namespace tessella::mesh_detail
