// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One small interface over sparse SPD solvers: Eigen's direct LDL^T for small
// systems and preconditioned conjugate gradients for large ones (always built),
// plus two optional back-ends chosen at build time: SuiteSparse's CHOLMOD
// (supernodal Cholesky) and conjugate gradients preconditioned by hypre's
// BoomerAMG (iterations nearly independent of the mesh size). Every FE problem
// in solvers/ is symmetric positive definite after Dirichlet elimination, so
// these cover them; failures become exceptions instead of silent garbage.

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace tessella::solvers {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Direct and ConjugateGradient are Eigen's (always available); Cholmod and
/// AmgCG exist when Tessella was built with TESSELLA_WITH_CHOLMOD /
/// TESSELLA_WITH_HYPRE (solverAvailable() tells). Requesting a back-end that is
/// not built throws InvalidProblemError naming the CMake option.
enum class SolverMethod { Auto, Direct, ConjugateGradient, Cholmod, AmgCG };
enum class Preconditioner { Jacobi, IncompleteCholesky };

std::string toString(SolverMethod method);
/// Whether this build of Tessella contains the back-end (Auto is always available).
bool solverAvailable(SolverMethod method);

namespace detail {
class ExternalSolver;  // CHOLMOD / hypre back-ends (solvers/src/external_solver.hpp)
}

struct LinearSolverOptions {
  SolverMethod method = SolverMethod::Auto;
  Preconditioner preconditioner = Preconditioner::IncompleteCholesky;
  /// CG (Eigen's or hypre's) stops when ||b - A x|| <= tolerance * ||b||.
  double tolerance = 1e-10;
  /// CG iteration cap; 0 means 2 * (number of unknowns).
  int max_iterations = 0;
  /// Auto picks the direct solver (Eigen LDL^T) up to this many unknowns;
  /// above, AMG-preconditioned CG when hypre is built, else Eigen's CG.
  int auto_direct_max_unknowns = 100000;
  /// BoomerAMG strength threshold (hypre's advice: 0.25 in 2D, 0.5 in 3D).
  double amg_strong_threshold = 0.5;
  /// The direct solver rejects the matrix as singular when its smallest LDL^T
  /// pivot is below max(pivot_tolerance, 64 n eps) times its largest one (a
  /// singular SPD matrix factorises "successfully" with round-off pivots).
  double pivot_tolerance = 1e-12;
};

struct SolveReport {
  SolverMethod method = SolverMethod::Auto;  ///< the method actually used
  int unknowns = 0;
  int iterations = 0;              ///< CG iterations (0 for the direct solvers)
  double relative_residual = 0.0;  ///< ||b - A x|| / ||b|| of the returned x
};

/// Factorise (or precondition) once with compute(), then solve() any number of
/// right-hand sides. Throws FactorizationError / ConvergenceError.
class LinearSolver {
 public:
  explicit LinearSolver(LinearSolverOptions options = {});
  ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;  // owns factorisations; hold it by pointer to move it
  LinearSolver& operator=(const LinearSolver&) = delete;

  /// Sets up the solver for the square SPD matrix A (a copy is kept, so A may die).
  /// The direct solvers (LDL^T, CHOLMOD) analyse a sparsity pattern once (the
  /// fill-reducing ordering and the symbolic factorisation): a compressed A with
  /// the same pattern as the previous one is factorised numerically only, with
  /// the same arithmetic as a fresh analysis (Newton iterations, shifted retries).
  void compute(const SparseMatrix& A);
  /// Symbolic analyses done so far (a fresh pattern, a method change or an
  /// uncompressed matrix each cost one).
  int analyses() const { return analyses_; }
  /// Solves A x = b; for CG, x0 is the initial guess (empty: zero).
  Eigen::VectorXd solve(const Eigen::VectorXd& b, const Eigen::VectorXd& x0 = {});

  bool ready() const { return ready_; }
  SolverMethod method() const { return method_; }
  const SolveReport& lastReport() const { return report_; }
  const LinearSolverOptions& options() const { return options_; }

 private:
  using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  // Lower|Upper on a row-major matrix lets Eigen run the CG product with OpenMP;
  // each row is summed by one thread, so the result does not depend on threads.
  using CgJacobi =
      Eigen::ConjugateGradient<RowSparse, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>>;
  using CgIchol = Eigen::ConjugateGradient<RowSparse, Eigen::Lower | Eigen::Upper,
                                           Eigen::IncompleteCholesky<double>>;

  LinearSolverOptions options_;
  SolverMethod method_ = SolverMethod::Auto;
  bool ready_ = false;
  RowSparse matrix_;  // owned copy: Eigen's CG keeps only a reference to its matrix
  Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
  CgJacobi cg_jacobi_;
  CgIchol cg_ichol_;
  std::unique_ptr<detail::ExternalSolver> external_;  // Cholmod / AmgCG
  SolveReport report_;
  // The pattern the direct solver analysed (empty: none), and for which method.
  bool samePattern(const SparseMatrix& A) const;
  void keepPattern(const SparseMatrix& A);
  SolverMethod analysed_method_ = SolverMethod::Auto;
  Eigen::Index analysed_size_ = -1;
  std::vector<SparseMatrix::StorageIndex> analysed_outer_, analysed_inner_;
  int analyses_ = 0;
};

/// Convenience: one-shot solve of A x = b.
Eigen::VectorXd solveLinear(const SparseMatrix& A, const Eigen::VectorXd& b,
                            const LinearSolverOptions& options = {}, SolveReport* report = nullptr);

}  // namespace tessella::solvers
