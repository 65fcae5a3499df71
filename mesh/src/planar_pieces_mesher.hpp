// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: a conforming triangle mesh of a surface made of planar pieces
// glued along shared sides — the fan triangles of a curved-sheet tissue, the
// walls of a 3D tissue (shared by the surface and the cell-by-cell volume
// meshers).
//
// Each piece (a planar polygon) is meshed in its own plane by a CGAL
// constrained Delaunay refinement whose boundary points are those of its
// sides. A side is shared by every piece that has it (two fan triangles, or
// all the walls around a tissue edge); it is subdivided once, uniformly to the
// edge bound, and every piece gets exactly its points. When the refinement of
// a piece splits a side (for the angle bound), the point goes to the shared
// side and the pieces on it are meshed again; rounds repeat until no side
// changes. Near sharp corners splits can bounce between neighbouring pieces,
// each side of a thin wedge refining the other, with side points multiplying:
// after kMaxRounds, once a round adds more side points than there were, or
// once a round from the fourth on adds at least 64 side points and no fewer
// than the round before (the splits no longer die out: the same pieces keep
// splitting each other's sides), the pieces left are refined inside only
// (Delaunay_mesher_no_edge_refinement_2), keeping their side points. The
// mesh stays conforming and exact; the angle bound may be missed next to
// those sides. Pieces marked `inside_only` (a fan
// triangle or a planar wall with a corner sharper than the bound, whose wedge
// would feed O(1/angle) points to its sides) are always refined inside only.
//
// Every refinement runs within a vertex budget (bounded_refinement.hpp) and
// raises a GeometryError naming the piece's owner instead of running on.

#include <array>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::mesh::detail {

struct PlanarPiece {
  std::vector<int> corners;  ///< point ids, counter-clockwise about `normal`
  Vec3 normal;               ///< unit normal of the piece's plane
  bool inside_only = false;  ///< never split the piece's sides
};

struct PlanarPiecesMesh {
  std::vector<Vec3> nodes;
  std::vector<int> node_point;                  ///< the input point of a node, -1 for added nodes
  std::vector<std::array<int, 3>> triangles;    ///< counter-clockwise about their piece's normal
  std::vector<int> triangle_piece;              ///< triangles are grouped by piece, in piece order

  /// Nodes along the side from point a to point b, both ends included.
  std::vector<int> sideNodes(int a, int b) const;

  // Side lookup for sideNodes: key (smaller, larger point id) -> nodes from the smaller.
  std::unordered_map<std::uint64_t, std::vector<int>> side_nodes;
};

/// Meshes the pieces. points: positions by point id (pieces name them);
/// max_edge: longest triangle edge, 0 = none; min_angle_degrees: 0 = none.
/// Nodes: the used input points by increasing id, then side points, then
/// points inside pieces. `owner(piece)` says whose piece it is, for errors
/// ("cell 12 (fan triangle 3)"), and `element(piece)` which element to name.
PlanarPiecesMesh meshPlanarPieces(const std::vector<Vec3>& points, const std::vector<PlanarPiece>& pieces,
                                  double max_edge, double min_angle_degrees,
                                  const std::function<std::string(std::size_t)>& owner,
                                  const std::function<ElementId(std::size_t)>& element);

}  // namespace tessella::mesh::detail
