// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Small-strain linear elasticity with P1 elements: plane stress / plane strain
// on flat triangle meshes in the xy-plane, 3D on tetrahedra, and membranes on
// triangle meshes anywhere in R^3 (curved sheets: in-plane plane-stress in each
// triangle's own frame, three displacement components per node, no bending
// stiffness). Young's modulus E and Poisson's ratio nu are per tissue cell.
// Boundary conditions: prescribed displacement components on facets or nodes,
// traction and pressure on facets, a uniform body force, and for membranes a
// pressure normal to the sheet (turgor).

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/solvers/linear_solver.hpp"
#include "tessella/tissue/enum_table.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace tessella::solvers {

enum class ElasticModel { PlaneStress, PlaneStrain, Solid, Membrane };
/// "plane_stress", "plane_strain", "solid", "membrane".
const EnumTable<ElasticModel>& elasticModels();

/// Fixes the selected components of the displacement to `value` on all nodes
/// of `facets` and on `nodes`.
struct DisplacementCondition {
  std::vector<int> facets;
  std::vector<int> nodes;
  std::array<bool, 3> fixed{true, true, true};  ///< which of x, y, z (z ignored in 2D)
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
};

/// Surface force per unit area (per unit length times thickness in 2D) on facets.
struct TractionCondition {
  std::vector<int> facets;
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();
};

/// Pressure p on boundary facets: traction = -p n, n the outward normal
/// (p > 0 pushes inwards). Interior facets are rejected (no outside there).
struct PressureCondition {
  std::vector<int> facets;
  double pressure = 0.0;
};

struct ElasticityProblem {
  ElasticModel model = ElasticModel::Solid;
  /// Per cell (indexed by element_cell), size 1 for uniform. E > 0, -1 < nu < 0.5.
  Eigen::VectorXd young = Eigen::VectorXd::Ones(1);
  Eigen::VectorXd poisson = Eigen::VectorXd::Constant(1, 0.3);
  double thickness = 1.0;  ///< triangles only: scales stiffness and loads (stresses do not depend on it)
  Eigen::Vector3d body_force = Eigen::Vector3d::Zero();  ///< per unit volume
  std::vector<DisplacementCondition> displacement;
  std::vector<TractionCondition> traction;
  std::vector<PressureCondition> pressure;
  /// Membrane only: pressure on the sheet, force p * area along each triangle's
  /// normal (x1 - x0) x (x2 - x0), so p > 0 inflates a closed surface whose
  /// triangles are listed counter-clockwise seen from outside. Not scaled by thickness.
  double membrane_pressure = 0.0;
  LinearSolverOptions linear;
};

/// Voigt order everywhere: [xx, yy, zz, yz, xz, xy]; strains use engineering
/// shears (gamma = 2 eps). In plane stress sigma_zz = 0 and eps_zz follows from
/// nu; in plane strain eps_zz = 0 and sigma_zz = nu (sigma_xx + sigma_yy).
/// Membranes: the in-plane tensors of each triangle expressed in global x, y, z
/// (the stress has no component along the triangle normal n; the strain has
/// eps_nn = -nu/(1-nu) tr(in-plane strain) along n).
struct ElasticityResult {
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> displacement;  ///< per node (z = 0 in 2D)
  Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor> strain;        ///< per element
  Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor> stress;        ///< per element
  /// Per cell (numCells(mesh) rows): measure-weighted average strain and
  /// stress, the stress's principal values (ascending) and directions (column
  /// k of matrix c goes with value k).
  Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor> cell_strain;
  Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor> cell_stress;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> principal_stress;
  std::vector<Eigen::Matrix3d> principal_directions;
  SolveReport report;
};

/// Assembles and solves. Throws InvalidProblemError for bad input and for an
/// under-constrained body (rigid-body modes left free by the displacement
/// conditions, checked before solving), FactorizationError / ConvergenceError
/// from the linear solver.
ElasticityResult solveElasticity(const mesh::FeMesh& mesh, const ElasticityProblem& problem);

/// 3x3 symmetric tensor from a Voigt stress row [xx, yy, zz, yz, xz, xy].
Eigen::Matrix3d voigtToTensor(const Eigen::Matrix<double, 1, 6>& v);

}  // namespace tessella::solvers
