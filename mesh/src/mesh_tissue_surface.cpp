// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Curved-sheet tissues (Embedding::Surface): each cell is meshed on the
// surface the tissue's geometry measures (tessella::polygonTriangulation()):
// the triangles from the vertex mean to each loop edge, or, for a cell whose
// fan folds over (not star-shaped from its vertex mean), the triangles of its
// own outline projected onto its best-fit plane and lifted back. So mesh areas
// equal cell areas exactly, also for non-planar, non-convex cells.
//
// Every such triangle is planar, so the sheet is a surface of planar pieces
// glued along shared sides: wall edges (shared by the two cells of the wall)
// and spokes (centre to vertex, shared by two fan triangles of one cell).
// planar_pieces_mesher.hpp meshes it conformingly.
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

#include "tessella/mesh/mesh_tissue.hpp"

#include <array>
#include <string>
#include <vector>

#include "planar_pieces_mesher.hpp"
#include "polygon_fan.hpp"
#include "tessella/mesh/geometry_check.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "wall_segments.hpp"

namespace tessella::mesh {

FeMesh meshSurfaceTissue(const Tissue& t, const MeshOptions& options) {
  validateMeshOptions(options);
  if (t.dim() != 2 || t.embedding() != Embedding::Surface)
    throw InputError(std::string("meshSurfaceTissue needs a curved-sheet (surface) 2D tissue, got a ") +
                     embeddingName(t.embedding()) + " tissue of dimension " + std::to_string(t.dim()));
  checkMeshable(t, options);
  checkElementLimit(t, options);
  const auto& topo = t.topology();

  // Points: vertex slots, then one fan centre per cell slot.
  const std::size_t centres = t.slots(0);
  std::vector<Vec3> points(t.slots(0) + t.cellSlots(), Vec3::Zero());
  for (VertexId v : t.vertices()) points[v.index()] = t.position(v);
  struct FanTriangle {
    int cell;
    int loop_position;
    double min_angle_degrees;
  };
  std::vector<detail::PlanarPiece> pieces;
  std::vector<FanTriangle> fans;
  for (CellId c : t.cells()) {
    const auto verts = topo.faceVertices(t.cellFace(c));
    const auto loop = detail::loopPositions(t, t.cellFace(c));
    const int centre = static_cast<int>(centres + c.index());
    // The surface the tissue measures the cell on: its fan from the vertex
    // mean, or where that folds the triangles of its own outline.
    const PolygonTriangulation surface = polygonTriangulation(loop);
    points[static_cast<std::size_t>(centre)] = surface.center;
    std::vector<std::array<int, 3>> triangles;
    if (surface.fan())
      for (std::size_t i = 0; i < verts.size(); ++i)
        triangles.push_back({centre, static_cast<int>(verts[i].index()),
                             static_cast<int>(verts[(i + 1) % verts.size()].index())});
    else
      for (const auto& tri : surface.triangles)
        triangles.push_back({static_cast<int>(verts[tri[0]].index()), static_cast<int>(verts[tri[1]].index()),
                             static_cast<int>(verts[tri[2]].index())});
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      const auto& tri = triangles[i];
      const std::array<Vec3, 3> corners{points[static_cast<std::size_t>(tri[0])], points[static_cast<std::size_t>(tri[1])],
                                        points[static_cast<std::size_t>(tri[2])]};
      const Vec3 normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
      if (!normal.allFinite())
        throw GeometryError("surface mesher: cell " + std::to_string(c.index()) + " has a degenerate " +
                                (surface.fan() ? "fan triangle at loop position " : "outline triangle ") +
                                std::to_string(i),
                            ElementId{2, c.index()});
      const double angle = detail::smallestAngleDegrees(corners);
      pieces.push_back({{tri[0], tri[1], tri[2]}, normal, options.min_angle_degrees > 0.0 && angle < options.min_angle_degrees});
      fans.push_back({static_cast<int>(c.index()), static_cast<int>(i), angle});
    }
  }
  const auto owner = [&](std::size_t i) {
    return "surface mesher: cell " + std::to_string(fans[i].cell) + " (triangle " +
           std::to_string(fans[i].loop_position) + ", smallest angle " + formatNumber(fans[i].min_angle_degrees, 6) +
           " degrees)";
  };
  const auto element = [&](std::size_t i) { return ElementId{2, static_cast<Index>(fans[i].cell)}; };
  const detail::PlanarPiecesMesh pm =
      detail::meshPlanarPieces(points, pieces, options.max_edge_length, options.min_angle_degrees, owner, element);

  FeMesh mesh;
  mesh.dim = 2;
  mesh.nodes.resize(static_cast<Eigen::Index>(pm.nodes.size()), 3);
  mesh.node_vertex.resize(static_cast<Eigen::Index>(pm.nodes.size()));
  for (std::size_t n = 0; n < pm.nodes.size(); ++n) {
    mesh.nodes.row(static_cast<Eigen::Index>(n)) = pm.nodes[n].transpose();
    const int p = pm.node_point[n];
    mesh.node_vertex(static_cast<Eigen::Index>(n)) = p >= 0 && static_cast<std::size_t>(p) < centres ? p : -1;
  }
  mesh.elements.resize(static_cast<Eigen::Index>(pm.triangles.size()), 3);
  mesh.element_cell.resize(static_cast<Eigen::Index>(pm.triangles.size()));
  for (std::size_t k = 0; k < pm.triangles.size(); ++k) {
    const auto r = static_cast<Eigen::Index>(k);
    mesh.elements.row(r) << pm.triangles[k][0], pm.triangles[k][1], pm.triangles[k][2];
    mesh.element_cell(r) = fans[static_cast<std::size_t>(pm.triangle_piece[k])].cell;
  }
  std::vector<std::array<int, 3>> facets;
  std::vector<bool> boundary;
  for (EdgeId e : t.edges()) {
    const auto nodes = pm.sideNodes(static_cast<int>(topo.edgeFrom(e).index()), static_cast<int>(topo.edgeTo(e).index()));
    const bool on_boundary = t.isBoundaryWall(handle_cast<WallId>(e));
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
      facets.push_back({nodes[k], nodes[k + 1], static_cast<int>(e.index())});
      boundary.push_back(on_boundary);
    }
  }
  detail::storeWallSegments(mesh, facets, boundary);
  return mesh;
}

}  // namespace tessella::mesh
