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
// GeometryError naming the cell or wall instead of reaching the mesher.

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/mesh/mesh_options.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella {

/// Meshes any tissue (dispatches on its embedding).
FeMesh meshTissue(const Tissue& tissue, const MeshOptions& options = {});

/// The three meshers behind meshTissue; each requires its embedding
/// (InputError otherwise) and runs checkMeshable first.
FeMesh meshPlanarTissue(const Tissue& tissue, const MeshOptions& options = {});
FeMesh meshSurfaceTissue(const Tissue& tissue, const MeshOptions& options = {});
FeMesh meshVolumeTissue(const Tissue& tissue, const MeshOptions& options = {});

}  // namespace tessella
