// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: the walls of a 3D tissue as one conforming triangle mesh, refined
// to a size and angle bound before any tetrahedron exists (the first half of
// the cell-by-cell volume mesher).
//
// A planar wall is meshed as its polygon, a non-planar wall as its fan
// triangles (the surface the tissue's geometry integrates over), each piece in
// its own plane by a CGAL constrained Delaunay refinement. The sides of the
// pieces — tissue edges, shared by every wall around them, and the spokes of
// non-planar fans — are subdivided once, uniformly, and every piece using a
// side gets exactly those points and the points the refinement of the pieces
// puts on it, in rounds (planar_pieces_mesher.hpp). A piece with a corner
// sharper than the angle bound is refined inside only: it never splits a side.

#include <array>
#include <vector>

#include "tessella/tissue/tissue.hpp"
#include "wall_triangulation.hpp"

namespace tessella::mesh::detail {

struct WallSurfaceMesh {
  /// Tissue vertices (live, in t.vertices() order), fan centres of non-planar
  /// walls, points on subdivided sides, then points inside walls.
  std::vector<Vec3> nodes;
  std::vector<int> node_vertex;                   ///< tissue vertex index, -1 for added nodes
  std::vector<std::array<int, 3>> triangles;      ///< oriented along their wall's normal
  std::vector<int> triangle_wall;                 ///< wall index of each triangle
  std::vector<std::size_t> wall_begin;            ///< triangles of wall slot w: [wall_begin[w], wall_begin[w + 1])
};

/// Meshes every wall. max_edge: longest triangle edge (0 = none);
/// min_angle_degrees: CGAL's angle bound inside the walls (0 = none).
/// Throws GeometryError naming the wall when a refinement exceeds its budget.
WallSurfaceMesh meshWallSurfaces(const Tissue& t, const WallTriangulation& walls, double max_edge,
                                 double min_angle_degrees);

}  // namespace tessella::mesh::detail
