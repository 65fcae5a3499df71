// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Quasi-static equilibrium: minimises a model's total energy E(x) over the
// free degrees of freedom by Newton's method with a backtracking (Armijo) line
// search on E. Tangent systems K d = -g are solved by solvers/' LinearSolver
// (Eigen LDL^T, CG, CHOLMOD or hypre AMG-CG). When K is not positive definite
// (compressed walls, a free rigid mode) or its step is not a descent
// direction, K + tau I is tried with a growing shift tau (Nocedal & Wright,
// Algorithm 3.3); near a stable equilibrium tau = 0 and the convergence is
// quadratic.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "tessella/mechanics/energy_model.hpp"
#include "tessella/solvers/linear_solver.hpp"
#include "tessella/tissue/enum_table.hpp"

namespace tessella::mechanics {

/// The direct solvers offered for the tangents (`mechanics.linear_solver`):
/// `auto` (CHOLMOD, when built, for tangents of at least
/// EquilibriumOptions::auto_cholmod_unknowns free dofs; else Eigen's
/// simplicial LDL^T below LinearSolverOptions' auto_direct_max_unknowns),
/// `ldlt` (always Eigen's LDL^T) and `cholmod`
/// (CHOLMOD's supernodal Cholesky; builds with TESSELLA_WITH_CHOLMOD). Only
/// direct solvers: the shifted tangents are factorised, an iterative solve of
/// an indefinite K would not detect it.
const EnumTable<solvers::SolverMethod>& tangentSolvers();

struct EquilibriumOptions {
  /// Converged when ||g_free|| <= relative_tolerance * forceScale(x) + absolute_tolerance,
  /// or below the round-off floor of the forces (EquilibriumReport::roundoff_floor).
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 0.0;
  int max_iterations = 50;
  /// Armijo constant c1: a step a d is accepted when E(x + a d) <= E(x) + c1 a g.d.
  double armijo = 1e-4;
  /// Backtracking factor on the step length, in (0, 1).
  double backtrack = 0.5;
  int max_backtracks = 40;
  /// Shifts tried per iteration before giving up (each 10x the previous).
  int max_shifts = 30;
  /// Options of the tangent solves (method, tolerances).
  solvers::LinearSolverOptions linear{};
  /// With linear.method Auto and CHOLMOD built: tangents of at least this many
  /// free dofs are factorised by CHOLMOD (supernodal; on the 3D 10^3-cell tissue
  /// 15-25 times faster than the simplicial LDL^T, docs/mechanics.md "Cost"),
  /// smaller ones by Eigen's LDL^T.
  Eigen::Index auto_cholmod_unknowns = 5000;
  /// Where the solve happens (for example "step 12, time 1.2"): named by the error.
  std::string context;
};

struct EquilibriumReport {
  int iterations = 0;       ///< Newton steps accepted
  double energy = 0.0;      ///< E at the returned x
  double residual = 0.0;    ///< ||g_free|| at the returned x
  double force_scale = 0.0; ///< forceScale(x) at the returned x
  /// The residual the test required: max(relative_tolerance * force_scale +
  /// absolute_tolerance, roundoff_floor).
  double tolerance = 0.0;
  /// 16 eps max|K_ii| |x|_inf sqrt(free dofs): the force error of positions
  /// rounded to eps |x| (from the last tangent; 0 before the first).
  double roundoff_floor = 0.0;
  /// Per iterate, starting with the initial x: ||g_free||, E, and (from the
  /// first step on) the shift tau and the step length a used to get there.
  std::vector<double> residuals;
  std::vector<double> energies;
  std::vector<double> shifts;
  std::vector<double> step_lengths;
  int linear_solves = 0;
  /// The solver the tangents were factorised with (Auto resolved; Auto when no tangent was needed).
  solvers::SolverMethod linear_method = solvers::SolverMethod::Auto;
  /// Symbolic analyses of the tangent's pattern (the fill-reducing ordering):
  /// one per solve when the model's pattern is fixed, later tangents and
  /// shifted retries are only refactorised.
  int analyses = 0;
};

/// Minimises model.energy over the entries of x whose `fixed` flag is 0
/// (fixed entries keep their values; `fixed` is empty or of length x.size()).
/// On success x holds the equilibrium. Throws EquilibriumError (x restored to
/// its value on entry) when it is not reached within options.max_iterations
/// or the line search fails; InputError for bad options or sizes.
EquilibriumReport solveEquilibrium(const EnergyModel& model, Eigen::VectorXd& x,
                                   const std::vector<std::uint8_t>& fixed, const EquilibriumOptions& options = {});

}  // namespace tessella::mechanics
