// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// P1 finite-element assembly on an FeMesh (triangles in R^3 or tetrahedra).
// All routines are OpenMP-parallel and deterministic: the result is
// bit-identical for any number of threads (mass and stiffness: see
// assembly_pattern.hpp; facet matrices: src/assemble_detail.hpp). Mass and
// stiffness build a sparsity pattern per call: to assemble repeatedly on one
// mesh, keep an AssemblyPattern.
// Coefficients are per element; use cellToElement() to map per-cell data.

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/solvers/linear_solver.hpp"
#include "tessella/tissue/enum_table.hpp"

#include <Eigen/Core>

#include <vector>

namespace tessella::solvers {

enum class MassType {
  Consistent,  ///< exact integral of phi_i phi_j
  Lumped       ///< row-sum diagonal: |e|/(d+1) per node; keeps positivity
};
/// "consistent", "lumped".
const EnumTable<MassType>& massTypes();

/// M_ij = sum_e c_e * int_e phi_i phi_j. Empty coefficient means c = 1.
SparseMatrix assembleMass(const mesh::FeMesh& mesh, MassType type, const Eigen::VectorXd& element_coefficient = {});

/// K_ij = sum_e c_e * int_e grad phi_i . grad phi_j. Empty coefficient means c = 1.
SparseMatrix assembleStiffness(const mesh::FeMesh& mesh, const Eigen::VectorXd& element_coefficient = {});

/// F_i = sum_e p_e * int_e phi_i (exact for a per-element constant density p).
Eigen::VectorXd assembleLoad(const mesh::FeMesh& mesh, const Eigen::VectorXd& element_density);

/// Boundary mass on wall facets: B_ij = sum_f c_f * int_f phi_i phi_j (segments
/// in 2D, triangles in 3D). Empty coefficient means c = 1. Sized numNodes.
SparseMatrix assembleFacetMass(const mesh::FeMesh& mesh, const std::vector<int>& facets,
                               const Eigen::VectorXd& facet_coefficient = {});

/// G_i = sum_f g_f * int_f phi_i for per-facet constant densities g (size = facets.size()).
Eigen::VectorXd assembleFacetLoad(const mesh::FeMesh& mesh, const std::vector<int>& facets,
                                  const Eigen::VectorXd& facet_density);

/// Measure of every element (area or volume), in parallel.
Eigen::VectorXd elementMeasures(const mesh::FeMesh& mesh);

}  // namespace tessella::solvers
