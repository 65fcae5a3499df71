// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: the two ways meshVolumeTissue fills a 3D tissue with tetrahedra
// (MeshOptions::volume_method; docs/meshing.md compares them), and what they
// share. Both receive a tissue that passed checkVolumeGeometry.

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/mesh/mesh_options.hpp"
#include "tessella/tissue/tissue.hpp"
#include "wall_triangulation.hpp"

namespace tessella::mesh::detail {

/// One TetGen run on the piecewise-linear complex of all walls, one region
/// per cell; TetGen refines the walls itself (volume_methods_whole_tissue.cpp).
FeMesh meshWholeTissue(const Tissue& t, const MeshOptions& options, const WallTriangulation& walls);

/// Walls meshed first (wall_surface_mesh.hpp), then one TetGen run per cell
/// that keeps those wall triangles, cells in parallel (volume_methods_cell_by_cell.cpp).
FeMesh meshCellByCell(const Tissue& t, const MeshOptions& options, const WallTriangulation& walls);

/// A point strictly inside cell c, clear of its walls by 1e-6 cbrt(volume):
/// the centroid when it qualifies (also for non-convex cells, checked by
/// winding number), else a point just inside one of its wall triangles.
/// Throws GeometryError naming the cell when there is none.
Vec3 cellSeed(const Tissue& t, const WallTriangulation& walls, CellId c);

}  // namespace tessella::mesh::detail
