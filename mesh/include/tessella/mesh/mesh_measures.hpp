// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Measures and quality figures of an FeMesh: element areas/volumes, per-cell
// sums (to compare with the tissue's cellMeasure), angles and radius-edge
// ratios. Free functions over the plain arrays, usable by solvers and tests.

#include <vector>

#include "tessella/mesh/fe_mesh.hpp"

namespace tessella::mesh {

/// Area of a triangle or volume of a tetrahedron (unsigned).
double elementMeasure(const FeMesh& mesh, int element);
/// Signed volume of a tetrahedron (positive for the FeMesh orientation).
double signedTetVolume(const FeMesh& mesh, int element);

/// Sum of element measures per cell index (size: largest cell index + 1, or
/// `cell_slots` if larger).
std::vector<double> cellMeasuresOfMesh(const FeMesh& mesh, std::size_t cell_slots = 0);
double totalMeasureOfMesh(const FeMesh& mesh);

/// Smallest angle (degrees) of a triangle.
double triangleMinAngleDegrees(const FeMesh& mesh, int element);
/// Circumradius / shortest edge of a tetrahedron.
double tetRadiusEdgeRatio(const FeMesh& mesh, int element);

/// Length (2D) or area (3D) of a wall facet.
double wallFacetMeasure(const FeMesh& mesh, int facet);

}  // namespace tessella::mesh
