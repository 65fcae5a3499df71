// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "planar_pieces_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

namespace tessella::mesh::detail {
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
using InteriorMesher = CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, Criteria>;

constexpr int kMaxRounds = 8;

/// A side shared by pieces, from the smaller point id `a` to `b`; its points
/// lie at parameters `params` (sorted, in (0, 1)).
struct Side {
  int a = -1, b = -1;
  Vec3 pa, pb;
  std::vector<double> params;
  std::vector<int> pieces;
  Vec3 at(double t) const { return pa + t * (pb - pa); }
};

std::uint64_t sideKey(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

/// A boundary point of a piece: a corner (point id), or point k of a side.
struct BoundaryPoint {
  Vec3 position;
  int corner = -1;
  int side = -1, k = -1;
};

/// Triangles over a piece's boundary points (index >= 0) and its own added
/// interior points (-(k + 1)).
struct PieceMesh {
  std::vector<Vec3> added;
  std::vector<std::array<int, 3>> triangles;
};

std::vector<BoundaryPoint> pieceBoundary(const PlanarPiece& p, const std::vector<int>& piece_sides,
                                         const std::vector<Side>& sides, const std::vector<Vec3>& points) {
  std::vector<BoundaryPoint> out;
  const std::size_t n = p.corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back({points[static_cast<std::size_t>(p.corners[i])], p.corners[i], -1, -1});
    const Side& s = sides[static_cast<std::size_t>(piece_sides[i])];
    const std::size_t m = s.params.size();
    const bool forward = s.a == p.corners[i];
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t k = forward ? j : m - 1 - j;
      out.push_back({s.at(s.params[k]), -1, piece_sides[i], static_cast<int>(k)});
    }
  }
  return out;
}

/// Meshes one piece in its plane. With `split_sides` the refinement may split
/// the piece's sides: those points go to `side_splits` as (side, parameter)
/// and the result is empty (the piece is meshed again once its sides have them).
PieceMesh meshPiece(const PlanarPiece& p, const std::vector<int>& piece_sides, const std::vector<BoundaryPoint>& boundary,
                    const std::vector<Side>& sides, double shape_bound, double max_edge, bool split_sides,
                    const std::function<GeometryError(const std::string&)>& error,
                    std::vector<std::pair<int, double>>& side_splits) {
  const Vec3 origin = boundary[0].position;
  Vec3 u = boundary[1].position - origin;
  u = (u - u.dot(p.normal) * p.normal).normalized();
  const Vec3 v = p.normal.cross(u);
  if (!u.allFinite() || !v.allFinite()) throw error("is degenerate (no plane through its first side)");
  const auto local = [&](const Vec3& x) { return K::Point_2((x - origin).dot(u), (x - origin).dot(v)); };

  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  handles.reserve(boundary.size());
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    auto h = cdt.insert(local(boundary[i].position));
    h->info().index = static_cast<int>(i);
    handles.push_back(h);
  }
  if (cdt.number_of_vertices() != boundary.size()) throw error("has coincident boundary points");
  double area2 = 0, extent = 0, min_spacing = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < handles.size(); ++i) {
    const auto &a = handles[i]->point(), &b = handles[(i + 1) % handles.size()]->point();
    cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
    min_spacing = std::min(min_spacing, std::sqrt(CGAL::squared_distance(a, b)));
    extent = std::max(extent, std::sqrt(CGAL::squared_distance(a, handles[0]->point())));
    area2 += a.x() * b.y() - a.y() * b.x();
  }
  const std::size_t budget = refinementBudget(boundary.size(), 0.5 * std::abs(area2), 2 * extent, min_spacing, max_edge);
  const auto exceeded = [&](std::size_t vertices) {
    throw error("did not finish refining within " + std::to_string(vertices) + " vertices (" +
                std::to_string(boundary.size()) + " boundary points); lower the angle bound or check the geometry");
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
    // A point on a side: every piece on that side must get it.
    if (!split_sides) throw error("got a point on its border from inside-only refinement (internal error)");
    split = true;
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity(), best_t = 0;
    for (int s : piece_sides) {
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

std::vector<int> PlanarPiecesMesh::sideNodes(int a, int b) const {
  const std::vector<int>& along = side_nodes.at(sideKey(a, b));
  if (a < b) return along;
  return {along.rbegin(), along.rend()};
}

PlanarPiecesMesh meshPlanarPieces(const std::vector<Vec3>& points, const std::vector<PlanarPiece>& pieces,
                                  double max_edge, double min_angle_degrees,
                                  const std::function<std::string(std::size_t)>& owner,
                                  const std::function<ElementId(std::size_t)>& element) {
  // Shared sides, first subdivided uniformly to max_edge.
  std::vector<Side> sides;
  std::vector<std::vector<int>> piece_sides(pieces.size());
  std::unordered_map<std::uint64_t, int> side_of;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const PlanarPiece& p = pieces[i];
    for (std::size_t k = 0; k < p.corners.size(); ++k) {
      const int a = p.corners[k], b = p.corners[(k + 1) % p.corners.size()];
      auto [it, inserted] = side_of.try_emplace(sideKey(a, b), static_cast<int>(sides.size()));
      if (inserted) {
        Side s;
        s.a = std::min(a, b);
        s.b = std::max(a, b);
        s.pa = points[static_cast<std::size_t>(s.a)];
        s.pb = points[static_cast<std::size_t>(s.b)];
        const double length = (s.pb - s.pa).norm();
        const int pieces_of_side = max_edge > 0 ? std::max(1, static_cast<int>(std::ceil(length / max_edge - 1e-9))) : 1;
        for (int j = 1; j < pieces_of_side; ++j) s.params.push_back(static_cast<double>(j) / pieces_of_side);
        sides.push_back(std::move(s));
      }
      piece_sides[i].push_back(it->second);
      sides[static_cast<std::size_t>(it->second)].pieces.push_back(static_cast<int>(i));
    }
  }

  // Rounds (see the header).
  const double shape_bound = min_angle_degrees > 0.0 ? shapeBound(min_angle_degrees) : 0.0;
  const bool refine = shape_bound > 0.0 || max_edge > 0.0;
  std::vector<PieceMesh> meshed(pieces.size());
  std::vector<int> dirty(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) dirty[i] = static_cast<int>(i);
  std::size_t side_points = 0;
  for (const Side& s : sides) side_points += s.params.size();
  bool last_round = !refine;
  std::size_t added_before = std::numeric_limits<std::size_t>::max();  // side points the previous round added
  for (int round = 0; !dirty.empty(); ++round) {
    last_round = last_round || round == kMaxRounds;
    std::vector<std::vector<std::pair<int, double>>> splits(dirty.size());
    std::vector<std::string> errors(dirty.size());
    std::vector<ElementId> error_elements(dirty.size());
#pragma omp parallel for schedule(dynamic, 16)
    for (std::size_t d = 0; d < dirty.size(); ++d) {
      const auto i = static_cast<std::size_t>(dirty[d]);
      try {
        const auto error = [&](const std::string& what) { return GeometryError(owner(i) + " " + what, element(i)); };
        meshed[i] = meshPiece(pieces[i], piece_sides[i], pieceBoundary(pieces[i], piece_sides[i], sides, points), sides,
                              shape_bound, max_edge, !last_round && !pieces[i].inside_only, error, splits[d]);
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
      // A piece that split its own side is meshed again too: its side points
      // must be the side's (bit-identical) points.
      if (!splits[d].empty()) mark[static_cast<std::size_t>(dirty[d])] = 1;
      for (const auto& [s, param] : splits[d]) {
        Side& side = sides[static_cast<std::size_t>(s)];
        if (!insertParam(side.params, param)) continue;
        ++added;
        for (int piece : side.pieces) mark[static_cast<std::size_t>(piece)] = 1;
      }
    }
    // Side points multiplying, or (once the first rounds have spread the
    // initial splits to the neighbouring pieces) splits no longer dying out:
    // what is left bounces between pieces, typically 3D walls around a sharp
    // corner, and every further round would only refine the walls there more
    // (docs/meshing.md, "Where the cell-by-cell time goes").
    const std::size_t min_added = 64;  // fewer new side points than this never end the rounds early
    last_round = round >= 1 && (added > std::max(side_points, min_added) ||
                                (round >= 3 && added >= std::max(added_before, min_added)));
    added_before = added;
    side_points += added;
    dirty.clear();
    for (std::size_t i = 0; i < pieces.size(); ++i)
      if (mark[i]) dirty.push_back(static_cast<int>(i));
  }

  // Nodes: used input points by id, side points, then inside points.
  PlanarPiecesMesh mesh;
  std::vector<int> point_node(points.size(), -1);
  for (const PlanarPiece& p : pieces)
    for (int c : p.corners) point_node[static_cast<std::size_t>(c)] = 0;
  for (std::size_t c = 0; c < points.size(); ++c)
    if (point_node[c] == 0) {
      point_node[c] = static_cast<int>(mesh.nodes.size());
      mesh.nodes.push_back(points[c]);
      mesh.node_point.push_back(static_cast<int>(c));
    }
  std::vector<int> side_first(sides.size());
  for (std::size_t s = 0; s < sides.size(); ++s) {
    side_first[s] = static_cast<int>(mesh.nodes.size());
    std::vector<int> along{point_node[static_cast<std::size_t>(sides[s].a)]};
    for (double param : sides[s].params) {
      along.push_back(static_cast<int>(mesh.nodes.size()));
      mesh.nodes.push_back(sides[s].at(param));
      mesh.node_point.push_back(-1);
    }
    along.push_back(point_node[static_cast<std::size_t>(sides[s].b)]);
    mesh.side_nodes.emplace(sideKey(sides[s].a, sides[s].b), std::move(along));
  }
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const auto boundary = pieceBoundary(pieces[i], piece_sides[i], sides, points);
    const int first_added = static_cast<int>(mesh.nodes.size());
    for (const Vec3& x : meshed[i].added) {
      mesh.nodes.push_back(x);
      mesh.node_point.push_back(-1);
    }
    for (auto tri : meshed[i].triangles) {
      for (int& n : tri) {
        if (n < 0) {
          n = first_added - n - 1;
        } else {
          const BoundaryPoint& b = boundary[static_cast<std::size_t>(n)];
          n = b.corner >= 0 ? point_node[static_cast<std::size_t>(b.corner)] : side_first[static_cast<std::size_t>(b.side)] + b.k;
        }
      }
      mesh.triangles.push_back(tri);
      mesh.triangle_piece.push_back(static_cast<int>(i));
    }
  }
  return mesh;
}

}  // namespace tessella::mesh::detail
