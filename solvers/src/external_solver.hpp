// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal interface of the optional linear-solver back-ends (CHOLMOD, hypre).
// Each lives in its own .cpp, compiled to a real solver when its library was
// found at configure time and to a factory that throws a clear error otherwise,
// so linear_solver.cpp never needs an #ifdef.

#include "tessella/solvers/linear_solver.hpp"

#include <memory>

namespace tessella::solvers::detail {

class ExternalSolver {
 public:
  virtual ~ExternalSolver() = default;
  /// Factorises / sets up the preconditioner for the square SPD matrix A.
  /// same_pattern: A has the pattern of the previous compute() on this object,
  /// whose symbolic analysis may be reused.
  virtual void compute(const SparseMatrix& A, bool same_pattern) = 0;
  /// Solves A x = b starting from x0 (empty: zero); sets the iterations done.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b, const Eigen::VectorXd& x0, int& iterations) = 0;
};

bool cholmodBuilt();
bool hypreBuilt();
/// Throw InvalidProblemError naming the CMake option when not built.
std::unique_ptr<ExternalSolver> makeCholmodSolver(const LinearSolverOptions& options);
std::unique_ptr<ExternalSolver> makeHypreSolver(const LinearSolverOptions& options);

}  // namespace tessella::solvers::detail
