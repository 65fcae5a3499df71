// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// P1 geometry of one simplex: its measure and the gradients of its hat
// functions. Works for triangles anywhere in R^3 (flat or on a curved sheet) and
// for tetrahedra: with J = [x1-x0, ..., xd-x0] (3 x d), the gradients are the
// columns of J (J^T J)^{-1}, i.e. tangential gradients in the simplex's own
// plane, and the measure is sqrt(det J^T J) / d!. No projection to xy is needed.

#include "tessella/mesh/fe_mesh.hpp"

#include <Eigen/Core>

#include <string_view>
#include <vector>

namespace tessella::solvers {

struct ElementGeometry {
  double measure = 0.0;  ///< area (triangle) or volume (tetrahedron), > 0
  /// Row a = gradient (in R^3) of the hat function of local node a; rows 0..dim are used.
  Eigen::Matrix<double, 4, 3> gradients = Eigen::Matrix<double, 4, 3>::Zero();
};

/// Geometry of element e. Throws InvalidProblemError for a degenerate element.
ElementGeometry elementGeometry(const mesh::FeMesh& mesh, int e);

/// Measure (length / area / volume) of the simplex spanned by `count` node
/// indices (2, 3 or 4) of the mesh.
double simplexMeasure(const mesh::FeMesh& mesh, const int* nodes, int count);

/// Checks the FeMesh invariants solvers rely on (shapes, index ranges) and
/// throws InvalidProblemError naming the first violation.
void checkMesh(const mesh::FeMesh& mesh);

/// Number of tissue cells the mesh refers to: max(element_cell) + 1.
int numCells(const mesh::FeMesh& mesh);

/// Expands a per-cell vector (indexed by cell id; size 1 means uniform) to one
/// value per element via element_cell. `what` names the quantity in errors.
/// With nonnegative = true a negative value is an InvalidProblemError.
Eigen::VectorXd cellToElement(const mesh::FeMesh& mesh, const Eigen::VectorXd& per_cell, std::string_view what,
                              bool nonnegative = false);

}  // namespace tessella::solvers
