// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// CHOLMOD back-end: SuiteSparse's supernodal Cholesky through Eigen's
// CholmodSupport. Like the LDL^T path, a "successful" factorisation of a
// numerically singular matrix is caught by CHOLMOD's reciprocal condition
// estimate (squared ratio of the extreme diagonal entries of L).
#include "external_solver.hpp"
#include "tessella/solvers/errors.hpp"
#include "tessella/tissue/format.hpp"

#include <limits>
#include <sstream>

#if TESSELLA_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#include <omp.h>
#endif

namespace tessella::solvers::detail {

#if TESSELLA_HAVE_CHOLMOD
namespace {

// Eigen keeps the factor protected; this exposes cholmod_rcond on it.
class CholmodLLT : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  double rcond() { return cholmod_rcond(m_cholmodFactor, &this->cholmod()); }
};

// CHOLMOD's supernodal factorisation forks CHOLMOD_OMP_NUM_THREADS threads (4
// in Debian's build, whatever the machine) for every large supernode, only to
// clear and copy memory; the dense work is BLAS's. On a small shared machine
// these teams wait on each other: on 2 cores under load, 45 % of a dome step's
// samples were libgomp spinning and task switches. While this guard lives,
// every team of the calling thread has one thread: nthreads-var 1 and dynamic
// threads on (both the thread's own ICVs) cap num_threads clauses too. The
// loops have no reductions, so the factor does not depend on the team size.
class OneThreadTeams {
 public:
  OneThreadTeams() : dynamic_(omp_get_dynamic()), threads_(omp_get_max_threads()) {
    omp_set_dynamic(1);
    omp_set_num_threads(1);
  }
  ~OneThreadTeams() {
    omp_set_num_threads(threads_);
    omp_set_dynamic(dynamic_);
  }
  OneThreadTeams(const OneThreadTeams&) = delete;
  OneThreadTeams& operator=(const OneThreadTeams&) = delete;

 private:
  int dynamic_, threads_;
};

class CholmodSolver final : public ExternalSolver {
 public:
  explicit CholmodSolver(const LinearSolverOptions& options) : options_(options) {
    llt_.cholmod().print = 0;  // library code does not print: failures become exceptions
  }

  void compute(const SparseMatrix& A, bool same_pattern) override {
    const auto n = static_cast<double>(A.rows());
    const OneThreadTeams one_thread;
    if (!same_pattern) llt_.analyzePattern(A);  // ordering (AMD, METIS when better) and supernodes
    llt_.factorize(A);
    if (llt_.info() != Eigen::Success)
      throw FactorizationError("LinearSolver (CHOLMOD): Cholesky factorisation failed: matrix is not positive definite");
    // rcond = (min L_ii / max L_ii)^2, comparable with the LDL^T pivot ratio.
    const double rc = llt_.rcond();
    const double tol = std::max(options_.pivot_tolerance, 64.0 * n * std::numeric_limits<double>::epsilon());
    if (!(rc > tol)) {
      std::ostringstream msg;
      msg << "LinearSolver (CHOLMOD): matrix is singular (reciprocal condition estimate " << formatNumber(rc, 6)
          << ", n = " << A.rows() << ")";
      throw FactorizationError(msg.str());
    }
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& b, const Eigen::VectorXd&, int& iterations) override {
    iterations = 0;
    const OneThreadTeams one_thread;
    Eigen::VectorXd x = llt_.solve(b);
    if (llt_.info() != Eigen::Success) throw FactorizationError("LinearSolver (CHOLMOD): solve failed");
    return x;
  }

 private:
  LinearSolverOptions options_;
  CholmodLLT llt_;
};

}  // namespace

bool cholmodBuilt() { return true; }
std::unique_ptr<ExternalSolver> makeCholmodSolver(const LinearSolverOptions& options) {
  return std::make_unique<CholmodSolver>(options);
}
#else
bool cholmodBuilt() { return false; }
std::unique_ptr<ExternalSolver> makeCholmodSolver(const LinearSolverOptions&) {
  throw InvalidProblemError(
      "LinearSolver: the CHOLMOD back-end is not built into this Tessella (configure with "
      "-DTESSELLA_WITH_CHOLMOD=ON and SuiteSparse, Debian libsuitesparse-dev, installed)");
}
#endif

}  // namespace tessella::solvers::detail
