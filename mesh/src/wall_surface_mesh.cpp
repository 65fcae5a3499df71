// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "wall_surface_mesh.hpp"

#include <string>

#include "planar_pieces_mesher.hpp"
#include "polygon_fan.hpp"

namespace tessella::mesh::detail {

WallSurfaceMesh meshWallSurfaces(const Tissue& t, const WallTriangulation& walls, double max_edge,
                                 double min_angle_degrees) {
  // Pieces, wall by wall: a planar wall's polygon, a non-planar wall's fan triangles.
  std::vector<PlanarPiece> pieces;
  std::vector<int> piece_wall;
  for (WallId w : t.walls()) {
    if (walls.wall_planar[w.index()]) {
      PlanarPiece p{{}, walls.wall_normal[w.index()]};
      std::vector<Vec3> loop;
      for (VertexId v : t.topology().faceVertices(handle_cast<FaceId>(w))) {
        p.corners.push_back(static_cast<int>(v.index()));
        loop.push_back(t.position(v));
      }
      // A wall with a corner sharper than the bound is refined inside only, like a sharp fan triangle: the
      // wedge cannot meet the bound, and its side splits would bounce between the walls around the corner.
      p.inside_only = min_angle_degrees > 0.0 && smallestCornerDegrees(loop, p.normal) < min_angle_degrees;
      pieces.push_back(std::move(p));
      piece_wall.push_back(static_cast<int>(w.index()));
      continue;
    }
    for (const auto& tri : walls.wall_triangles[w.index()]) {
      const std::array<Vec3, 3> c{walls.points[static_cast<std::size_t>(tri[0])], walls.points[static_cast<std::size_t>(tri[1])],
                                  walls.points[static_cast<std::size_t>(tri[2])]};
      // A sharp fan triangle is refined inside only, as on curved sheets.
      pieces.push_back({{tri[0], tri[1], tri[2]}, (c[1] - c[0]).cross(c[2] - c[0]).normalized(),
                        min_angle_degrees > 0.0 && smallestAngleDegrees(c) < min_angle_degrees});
      piece_wall.push_back(static_cast<int>(w.index()));
    }
  }
  const auto owner = [&](std::size_t i) {
    const WallId w(static_cast<Index>(piece_wall[i]));
    return "wall mesher: wall " + std::to_string(w.index()) + " " + wallCellsText(t, w);
  };
  const auto element = [&](std::size_t i) { return ElementId{2, static_cast<Index>(piece_wall[i])}; };
  PlanarPiecesMesh pm = meshPlanarPieces(walls.points, pieces, max_edge, min_angle_degrees, owner, element);

  WallSurfaceMesh mesh;
  mesh.nodes = std::move(pm.nodes);
  mesh.node_vertex.resize(pm.node_point.size());
  for (std::size_t n = 0; n < pm.node_point.size(); ++n)
    mesh.node_vertex[n] = pm.node_point[n] >= 0 && static_cast<std::size_t>(pm.node_point[n]) < walls.vertex_slots ? pm.node_point[n] : -1;
  mesh.triangles = std::move(pm.triangles);
  mesh.triangle_wall.resize(mesh.triangles.size());
  // Triangles come wall by wall (pieces were listed so).
  mesh.wall_begin.assign(t.slots(2) + 1, 0);
  std::size_t k = 0;
  for (std::size_t w = 0; w <= t.slots(2); ++w) {
    mesh.wall_begin[w] = k;
    for (; k < mesh.triangles.size() && piece_wall[static_cast<std::size_t>(pm.triangle_piece[k])] == static_cast<int>(w); ++k)
      mesh.triangle_wall[k] = static_cast<int>(w);
  }
  return mesh;
}

}  // namespace tessella::mesh::detail
