#pragma once
// One small interface over Eigen's sparse SPD solvers: a direct LDL^T for small
// systems, preconditioned conjugate gradients for large ones. Every FE problem
// in solvers/ is symmetric positive definite after Dirichlet elimination, so
// these two cover them; failures become exceptions instead of silent garbage.

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <string>

namespace tessella {

using SparseMatrix = Eigen::SparseMatrix<double>;

enum class SolverMethod { Auto, Direct, ConjugateGradient };
enum class Preconditioner { Jacobi, IncompleteCholesky };

std::string toString(SolverMethod method);

struct LinearSolverOptions {
  SolverMethod method = SolverMethod::Auto;
  Preconditioner preconditioner = Preconditioner::IncompleteCholesky;
  /// CG stops when ||b - A x|| <= tolerance * ||b||.
  double tolerance = 1e-10;
  /// CG iteration cap; 0 means 2 * (number of unknowns).
  int max_iterations = 0;
  /// Auto picks the direct solver up to this many unknowns, CG above.
  int auto_direct_max_unknowns = 100000;
  /// The direct solver rejects the matrix as singular when its smallest LDL^T
  /// pivot is below max(pivot_tolerance, 64 n eps) times its largest one (a
  /// singular SPD matrix factorises "successfully" with round-off pivots).
  double pivot_tolerance = 1e-12;
};

struct SolveReport {
  SolverMethod method = SolverMethod::Auto;  ///< the method actually used
  int unknowns = 0;
  int iterations = 0;              ///< CG iterations (0 for the direct solver)
  double relative_residual = 0.0;  ///< ||b - A x|| / ||b|| of the returned x
};

/// Factorise (or precondition) once with compute(), then solve() any number of
/// right-hand sides. Throws FactorizationError / ConvergenceError.
class LinearSolver {
 public:
  explicit LinearSolver(LinearSolverOptions options = {});

  /// Sets up the solver for the square SPD matrix A (a copy is kept, so A may die).
  void compute(const SparseMatrix& A);
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
  SolveReport report_;
};

/// Convenience: one-shot solve of A x = b.
Eigen::VectorXd solveLinear(const SparseMatrix& A, const Eigen::VectorXd& b,
                            const LinearSolverOptions& options = {}, SolveReport* report = nullptr);

}  // namespace tessella
