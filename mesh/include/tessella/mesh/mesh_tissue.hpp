// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// meshTissue(): any tissue -> a conforming finite-element mesh that respects
// its cells. Every element lies in exactly one cell, every wall is a union of
// element facets, and two cells sharing a wall share the nodes on it.
//
//   Embedding::Planar   triangles (CGAL constrained Delaunay refinement)
//   Embedding::Surface  triangles on each cell's fan surface (the surface the
//                       geometry measures), conforming across walls
//   Embedding::Volume   tetrahedra (TetGen), walls as marked facets
//
// The tissue is checked first (checkMeshable): bad geometry raises a
// GeometryError naming the cell or wall instead of reaching the mesher. Then
// the element count the size bounds ask for is estimated, and a mesh larger
// than options.max_elements is refused (InputError) before any meshing.

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/mesh/mesh_options.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::mesh {

/// Meshes any tissue (dispatches on its embedding).
FeMesh meshTissue(const Tissue& tissue, const MeshOptions& options = {});

/// A lower bound on the number of elements the size bounds ask for:
/// 2D and curved tissues: total area / (sqrt(3)/4 h^2) triangles, h =
/// max_edge_length (no triangle with edges <= h is larger than the
/// equilateral one). 3D tissues: total volume / max_volume tetrahedra, and,
/// cell by cell, the walls' triangles (wall area / (sqrt(3)/4 h^2), each wall
/// counted for every cell it bounds) divided by the 4 faces of a tetrahedron;
/// the larger of the two. 0 when no size bound is set.
double estimatedElementCount(const Tissue& tissue, const MeshOptions& options);

/// Throws InputError naming the estimate, the size bound and the limit when
/// estimatedElementCount() exceeds options.max_elements (0 = no limit).
void checkElementLimit(const Tissue& tissue, const MeshOptions& options);

/// The three meshers behind meshTissue; each requires its embedding
/// (InputError otherwise) and runs checkMeshable and checkElementLimit first.
FeMesh meshPlanarTissue(const Tissue& tissue, const MeshOptions& options = {});
FeMesh meshSurfaceTissue(const Tissue& tissue, const MeshOptions& options = {});
FeMesh meshVolumeTissue(const Tissue& tissue, const MeshOptions& options = {});

}  // namespace tessella::mesh
