// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: every wall of a 3D tissue as triangles over one point list (the
// tissue's vertex slots, then one fan centre per wall slot): the surface the
// tissue's geometry integrates over (tessella::polygonTriangulation()), the
// fan from the vertex mean where it does not fold, else the triangulation of
// the wall's outline projected onto its best-fit plane and lifted back, planar
// or not. Triangles run the same way round as the wall loop (normal = the
// wall's normal).

#include <array>
#include <string>
#include <vector>

#include "tessella/mesh/geometry_check.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::mesh::detail {

struct WallTriangulation {
  std::vector<Vec3> points;  ///< vertex slots, then wall slots (fan centres)
  std::vector<std::vector<std::array<int, 3>>> wall_triangles;  ///< per wall slot
  std::vector<std::uint8_t> wall_planar;                         ///< per wall slot
  std::vector<Vec3> wall_normal;                                 ///< unit, per wall slot
  int centerPoint(WallId w) const { return static_cast<int>(vertex_slots + w.index()); }
  std::size_t vertex_slots = 0;
};

/// Builds the triangulation and reports the first wall defect it meets
/// (zero area, pinched or self-intersecting outline).
MeshabilityReport triangulateWalls(const Tissue& t, double tolerance, WallTriangulation& out);

/// The 3D part of the geometry check; fills `walls` for the volume mesher.
MeshabilityReport checkVolumeGeometry(const Tissue& t, const MeshOptions& options, WallTriangulation& walls);

/// "(cells 3, 8)": the cells on either side of a wall, for messages.
std::string wallCellsText(const Tissue& t, WallId w);

/// Bounding-box diagonal of the live vertices (the length scale of tolerances).
double tissueScale(const Tissue& t);

}  // namespace tessella::mesh::detail
