// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Would a planned 3D division make walls that cross? A wall's surface is the
// one the tissue measures and the mesher triangulates (polygonTriangulation():
// a fan from the vertex mean, or where that folds the kernel's centroid or
// the outline's triangles). Dividing a cell changes the surfaces of the new
// wall, of the pieces of every wall it cuts, and of every wall given a new
// vertex on an edge the plane crosses (its vertex mean moves); in thin,
// curved cells such a surface can pass through another wall, and the mesher
// then refuses the tissue. DivisionScheduler refuses such a plane and tries
// the next one (docs/growth.md, "The scheduler and degenerate cases").

#include <string>

#include "tessella/tissue/cell_split_plan.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::growth {

/// Empty when dividing cell `c` of a 3D tissue by `plan` (planCellSplit3D)
/// makes no wall surface cross another wall's, or itself, where none crossed
/// before; else what would cross, naming the walls, their cells and a point
/// near the crossing. Tested pair of triangles by pair with the mesher's own
/// test (mesh::trianglesCross, tessella/mesh/triangle_pair.hpp: CGAL's exact
/// predicates), against the walls of every cell that shares a vertex with a
/// changed wall. Reads the tissue only.
std::string divisionCrossing(const Tissue& t, CellId c, const CellSplitPlan3D& plan);

}  // namespace tessella::growth
