// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// hypre back-end: conjugate gradients preconditioned by one BoomerAMG V-cycle.
// Debian's hypre is built with MPI, so MPI is initialised here when the
// program has not done it (and finalised at exit); every solver works on
// MPI_COMM_SELF, i.e. serially in each process, with hypre's OpenMP threads.
// AMG settings are the usual ones for 3D Poisson-like problems: HMIS
// coarsening, extended+i interpolation truncated to 4 entries, one sweep of
// symmetric hybrid Gauss-Seidel (the preconditioner stays symmetric for CG).
#include "external_solver.hpp"
#include "tessella/solvers/errors.hpp"

#include <sstream>
#include <vector>

#if TESSELLA_HAVE_HYPRE
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <cstdlib>
#include <mutex>
#endif

namespace tessella::solvers::detail {

#if TESSELLA_HAVE_HYPRE
namespace {

void finalizeMpi() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) {
    HYPRE_Finalize();
    MPI_Finalize();
  }
}

void ensureInitialised() {
  static std::once_flag once;
  std::call_once(once, [] {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) {
      int provided = 0;
      if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        throw SolverError("LinearSolver (hypre): MPI_Init_thread failed");
      std::atexit(finalizeMpi);  // only when we started MPI: the caller owns it otherwise
    }
    HYPRE_Init();
  });
}

[[noreturn]] void fail(const char* what, HYPRE_Int code) {
  std::ostringstream msg;
  msg << "LinearSolver (hypre): " << what << " failed (hypre error code " << code << ")";
  HYPRE_ClearAllErrors();
  throw SolverError(msg.str());
}

void check(HYPRE_Int code, const char* what) {
  if (code != 0) fail(what, code);
}

class HypreSolver final : public ExternalSolver {
 public:
  explicit HypreSolver(const LinearSolverOptions& options) : options_(options) { ensureInitialised(); }
  ~HypreSolver() override { release(); }
  HypreSolver(const HypreSolver&) = delete;
  HypreSolver& operator=(const HypreSolver&) = delete;

  void compute(const SparseMatrix& A, bool /*same_pattern*/) override {
    release();
    n_ = static_cast<HYPRE_Int>(A.rows());
    const MPI_Comm comm = MPI_COMM_SELF;
    // CSR rows from the (symmetric) column-major matrix: its transpose.
    const Eigen::SparseMatrix<double, Eigen::RowMajor, HYPRE_Int> R = A;
    std::vector<HYPRE_Int> ncols(static_cast<std::size_t>(n_)), rows(static_cast<std::size_t>(n_));
    for (HYPRE_Int i = 0; i < n_; ++i) {
      rows[static_cast<std::size_t>(i)] = i;
      ncols[static_cast<std::size_t>(i)] = R.outerIndexPtr()[i + 1] - R.outerIndexPtr()[i];
    }
    check(HYPRE_IJMatrixCreate(comm, 0, n_ - 1, 0, n_ - 1, &ij_matrix_), "IJMatrixCreate");
    check(HYPRE_IJMatrixSetObjectType(ij_matrix_, HYPRE_PARCSR), "IJMatrixSetObjectType");
    check(HYPRE_IJMatrixSetRowSizes(ij_matrix_, ncols.data()), "IJMatrixSetRowSizes");
    check(HYPRE_IJMatrixInitialize(ij_matrix_), "IJMatrixInitialize");
    check(HYPRE_IJMatrixSetValues(ij_matrix_, n_, ncols.data(), rows.data(), R.innerIndexPtr(), R.valuePtr()),
          "IJMatrixSetValues");
    check(HYPRE_IJMatrixAssemble(ij_matrix_), "IJMatrixAssemble");
    check(HYPRE_IJMatrixGetObject(ij_matrix_, reinterpret_cast<void**>(&parcsr_)), "IJMatrixGetObject");
    for (HYPRE_IJVector* v : {&ij_b_, &ij_x_}) {
      check(HYPRE_IJVectorCreate(comm, 0, n_ - 1, v), "IJVectorCreate");
      check(HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR), "IJVectorSetObjectType");
      check(HYPRE_IJVectorInitialize(*v), "IJVectorInitialize");
      check(HYPRE_IJVectorAssemble(*v), "IJVectorAssemble");
    }
    HYPRE_IJVectorGetObject(ij_b_, reinterpret_cast<void**>(&par_b_));
    HYPRE_IJVectorGetObject(ij_x_, reinterpret_cast<void**>(&par_x_));

    check(HYPRE_BoomerAMGCreate(&amg_), "BoomerAMGCreate");
    HYPRE_BoomerAMGSetPrintLevel(amg_, 0);
    HYPRE_BoomerAMGSetCoarsenType(amg_, 10);  // HMIS
    HYPRE_BoomerAMGSetInterpType(amg_, 6);    // extended+i
    HYPRE_BoomerAMGSetPMaxElmts(amg_, 4);
    HYPRE_BoomerAMGSetStrongThreshold(amg_, options_.amg_strong_threshold);
    HYPRE_BoomerAMGSetRelaxType(amg_, 6);  // symmetric hybrid Gauss-Seidel
    HYPRE_BoomerAMGSetNumSweeps(amg_, 1);
    HYPRE_BoomerAMGSetMaxIter(amg_, 1);  // one V-cycle per CG step
    HYPRE_BoomerAMGSetTol(amg_, 0.0);

    check(HYPRE_ParCSRPCGCreate(comm, &pcg_), "ParCSRPCGCreate");
    HYPRE_PCGSetTol(pcg_, options_.tolerance);
    HYPRE_PCGSetAbsoluteTol(pcg_, 0.0);
    HYPRE_PCGSetMaxIter(pcg_, options_.max_iterations > 0 ? options_.max_iterations : 2 * n_);
    HYPRE_PCGSetTwoNorm(pcg_, 1);  // ||r||_2 <= tol ||b||_2, as Eigen's CG
    HYPRE_PCGSetPrintLevel(pcg_, 0);
    HYPRE_PCGSetLogging(pcg_, 1);
    HYPRE_PCGSetPrecond(pcg_, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), amg_);
    check(HYPRE_ParCSRPCGSetup(pcg_, parcsr_, par_b_, par_x_), "BoomerAMG/PCG setup");
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& b, const Eigen::VectorXd& x0, int& iterations) override {
    std::vector<HYPRE_Int> idx(static_cast<std::size_t>(n_));
    for (HYPRE_Int i = 0; i < n_; ++i) idx[static_cast<std::size_t>(i)] = i;
    const Eigen::VectorXd start = x0.size() == n_ ? x0 : Eigen::VectorXd::Zero(n_);
    HYPRE_IJVectorSetValues(ij_b_, n_, idx.data(), b.data());
    HYPRE_IJVectorSetValues(ij_x_, n_, idx.data(), start.data());
    const HYPRE_Int code = HYPRE_ParCSRPCGSolve(pcg_, parcsr_, par_b_, par_x_);
    // Non-convergence is a hypre "error" too: the caller measures the residual
    // and reports it, so only clear the flag here.
    if (code != 0) HYPRE_ClearAllErrors();
    HYPRE_Int its = 0;
    HYPRE_PCGGetNumIterations(pcg_, &its);
    iterations = static_cast<int>(its);
    Eigen::VectorXd x(n_);
    HYPRE_IJVectorGetValues(ij_x_, n_, idx.data(), x.data());
    return x;
  }

 private:
  void release() {
    if (pcg_) HYPRE_ParCSRPCGDestroy(pcg_);
    if (amg_) HYPRE_BoomerAMGDestroy(amg_);
    if (ij_b_) HYPRE_IJVectorDestroy(ij_b_);
    if (ij_x_) HYPRE_IJVectorDestroy(ij_x_);
    if (ij_matrix_) HYPRE_IJMatrixDestroy(ij_matrix_);
    pcg_ = amg_ = nullptr;
    ij_b_ = ij_x_ = nullptr;
    ij_matrix_ = nullptr;
  }

  LinearSolverOptions options_;
  HYPRE_Int n_ = 0;
  HYPRE_IJMatrix ij_matrix_ = nullptr;
  HYPRE_ParCSRMatrix parcsr_ = nullptr;
  HYPRE_IJVector ij_b_ = nullptr, ij_x_ = nullptr;
  HYPRE_ParVector par_b_ = nullptr, par_x_ = nullptr;
  HYPRE_Solver amg_ = nullptr, pcg_ = nullptr;
};

}  // namespace

bool hypreBuilt() { return true; }
std::unique_ptr<ExternalSolver> makeHypreSolver(const LinearSolverOptions& options) {
  return std::make_unique<HypreSolver>(options);
}
#else
bool hypreBuilt() { return false; }
std::unique_ptr<ExternalSolver> makeHypreSolver(const LinearSolverOptions&) {
  throw InvalidProblemError(
      "LinearSolver: the hypre BoomerAMG back-end (AmgCG) is not built into this Tessella (configure with "
      "-DTESSELLA_WITH_HYPRE=ON and hypre, Debian libhypre-dev, installed)");
}
#endif

}  // namespace tessella::solvers::detail
