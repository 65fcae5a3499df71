// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// LinearSolver: both methods solve SPD systems to their tolerance, report what
// they did, and refuse singular / indefinite matrices or non-convergence.
#include <catch2/catch.hpp>

#include "tessella/solvers/errors.hpp"
#include "tessella/solvers/linear_solver.hpp"

#include <vector>

using namespace tessella;
using namespace tessella::solvers;

namespace {

// 1D Laplacian with Dirichlet ends (tridiagonal 2, -1): SPD, cond ~ n^2.
SparseMatrix laplacian1d(int n, bool neumann = false) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    double diag = 2.0;
    if (neumann && (i == 0 || i == n - 1)) diag = 1.0;  // rows sum to 0: singular
    t.emplace_back(i, i, diag);
    if (i > 0) t.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0);
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace

TEST_CASE("LinearSolver solves an SPD system with every method", "[solvers][linear]") {
  const int n = 300;
  const SparseMatrix A = laplacian1d(n);
  Eigen::VectorXd x_true(n);
  for (int i = 0; i < n; ++i) x_true[i] = std::sin(0.05 * i) + 0.01 * i;
  const Eigen::VectorXd b = A * x_true;

  struct Case {
    SolverMethod method;
    Preconditioner pre;
  };
  for (const Case c : {Case{SolverMethod::Direct, Preconditioner::Jacobi},
                       Case{SolverMethod::ConjugateGradient, Preconditioner::Jacobi},
                       Case{SolverMethod::ConjugateGradient, Preconditioner::IncompleteCholesky}}) {
    LinearSolverOptions opt;
    opt.method = c.method;
    opt.preconditioner = c.pre;
    opt.tolerance = 1e-12;
    LinearSolver solver(opt);
    solver.compute(A);
    const Eigen::VectorXd x = solver.solve(b);
    const SolveReport& r = solver.lastReport();
    CHECK(r.method == c.method);
    CHECK(r.unknowns == n);
    CHECK(r.relative_residual <= 1e-12);
    CHECK(r.relative_residual == Approx((b - A * x).norm() / b.norm()).margin(1e-18));
    // cond(A) ~ 4e4: the error is bounded by cond * residual.
    CHECK((x - x_true).norm() / x_true.norm() < 1e-7);
    if (c.method == SolverMethod::Direct) {
      CHECK(r.iterations == 0);
    } else {
      CHECK(r.iterations > 0);
    }
  }
}

TEST_CASE("LinearSolver Auto picks direct for small and CG (AMG when built) for large systems", "[solvers][linear]") {
  LinearSolverOptions opt;
  opt.auto_direct_max_unknowns = 100;
  LinearSolver small(opt), large(opt);
  small.compute(laplacian1d(100));
  large.compute(laplacian1d(101));
  CHECK(small.method() == SolverMethod::Direct);
  CHECK(large.method() ==
        (solverAvailable(SolverMethod::AmgCG) ? SolverMethod::AmgCG : SolverMethod::ConjugateGradient));
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(101);
  const Eigen::VectorXd x = large.solve(b);
  CHECK((laplacian1d(101) * x - b).norm() <= 1e-10 * b.norm());
}

TEST_CASE("LinearSolver rejects singular and indefinite matrices", "[solvers][linear]") {
  LinearSolverOptions opt;
  opt.method = SolverMethod::Direct;
  LinearSolver solver(opt);
  CHECK_THROWS_AS(solver.compute(laplacian1d(50, /*neumann=*/true)), FactorizationError);
  CHECK_FALSE(solver.ready());
  CHECK_THROWS_AS(solver.solve(Eigen::VectorXd::Ones(50)), SolverError);

  SparseMatrix indefinite(3, 3);
  indefinite.insert(0, 0) = 1.0;
  indefinite.insert(1, 1) = -1.0;
  indefinite.insert(2, 2) = 2.0;
  CHECK_THROWS_AS(solver.compute(indefinite), FactorizationError);

  // A larger singular matrix, whose round-off pivot is bigger (the pure-Neumann
  // Laplacian of a 2D grid): still refused.
  {
    const int g = 60, nn = g * g;
    std::vector<Eigen::Triplet<double>> t;
    auto id = [g](int i, int j) { return j * g + i; };
    for (int j = 0; j < g; ++j)
      for (int i = 0; i < g; ++i) {
        if (i + 1 < g) {
          t.emplace_back(id(i, j), id(i, j), 1.0), t.emplace_back(id(i + 1, j), id(i + 1, j), 1.0);
          t.emplace_back(id(i, j), id(i + 1, j), -1.0), t.emplace_back(id(i + 1, j), id(i, j), -1.0);
        }
        if (j + 1 < g) {
          t.emplace_back(id(i, j), id(i, j), 1.0), t.emplace_back(id(i, j + 1), id(i, j + 1), 1.0);
          t.emplace_back(id(i, j), id(i, j + 1), -1.0), t.emplace_back(id(i, j + 1), id(i, j), -1.0);
        }
      }
    SparseMatrix L(nn, nn);
    L.setFromTriplets(t.begin(), t.end());
    CHECK_THROWS_AS(solver.compute(L), FactorizationError);
    SparseMatrix shifted = L;  // + 1e-3 I is SPD again
    for (int i = 0; i < nn; ++i) shifted.coeffRef(i, i) += 1e-3;
    CHECK_NOTHROW(solver.compute(shifted));
  }

  SparseMatrix rect(3, 2);
  CHECK_THROWS_AS(solver.compute(rect), InvalidProblemError);
}

TEST_CASE("LinearSolver reports a non-converged CG solve", "[solvers][linear]") {
  LinearSolverOptions opt;
  opt.method = SolverMethod::ConjugateGradient;
  opt.preconditioner = Preconditioner::Jacobi;
  opt.max_iterations = 3;
  LinearSolver solver(opt);
  solver.compute(laplacian1d(400));
  try {
    solver.solve(Eigen::VectorXd::Ones(400));
    FAIL("expected ConvergenceError");
  } catch (const ConvergenceError& e) {
    CHECK(std::string(e.what()).find("did not converge in 3 iterations") != std::string::npos);
  }
}

TEST_CASE("LinearSolver: zero right-hand side gives zero, CG warm start converges at once", "[solvers][linear]") {
  const SparseMatrix A = laplacian1d(80);
  LinearSolverOptions opt;
  opt.method = SolverMethod::ConjugateGradient;
  opt.preconditioner = Preconditioner::Jacobi;  // (incomplete Cholesky is exact on a tridiagonal matrix)
  LinearSolver solver(opt);
  solver.compute(A);
  CHECK(solver.solve(Eigen::VectorXd::Zero(80)).isZero(0.0));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(80, 1.0, 2.0);
  const Eigen::VectorXd x = solver.solve(b);
  const int cold = solver.lastReport().iterations;
  CHECK(cold > 1);
  solver.solve(b, x);
  CHECK(solver.lastReport().iterations < cold);
  solver.solve(b, solver.solve(b, x));  // an exact guess needs no step at all
  CHECK(solver.lastReport().iterations <= 1);
}

TEST_CASE("LinearSolver analyses a repeated pattern once, with the same result as a fresh solver",
          "[solvers][linear]") {
  // A 2D grid Laplacian plus a diagonal c I: SPD for c > 0, singular for c = 0,
  // indefinite for c < 0. Every matrix below has the same pattern but the last.
  const int g = 20, n = g * g;
  auto grid = [&](double c, bool extra_entry = false) {
    std::vector<Eigen::Triplet<double>> t;
    for (int j = 0; j < g; ++j)
      for (int i = 0; i < g; ++i) {
        const int k = j * g + i;
        t.emplace_back(k, k, c + 0.01 * (k % 7));
        for (const int l : {i + 1 < g ? k + 1 : -1, j + 1 < g ? k + g : -1}) {
          if (l < 0) continue;
          t.emplace_back(k, k, 1.0), t.emplace_back(l, l, 1.0);
          t.emplace_back(k, l, -1.0), t.emplace_back(l, k, -1.0);
        }
      }
    if (extra_entry) t.emplace_back(0, n - 1, 0.0), t.emplace_back(n - 1, 0, 0.0);
    SparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    return A;
  };
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b[i] = std::cos(0.3 * i);
  std::vector<SolverMethod> methods{SolverMethod::Direct};
  if (solverAvailable(SolverMethod::Cholmod)) methods.push_back(SolverMethod::Cholmod);
  for (const SolverMethod method : methods) {
    CAPTURE(toString(method));
    LinearSolverOptions opt;
    opt.method = method;
    LinearSolver solver(opt);
    auto fresh = [&](const SparseMatrix& A) {
      LinearSolver one(opt);
      one.compute(A);
      CHECK(one.analyses() == 1);
      return Eigen::VectorXd(one.solve(b));
    };
    for (const double c : {0.5, 2.0}) {
      solver.compute(grid(c));
      CHECK((solver.solve(b) - fresh(grid(c))).cwiseAbs().maxCoeff() == 0.0);  // the same arithmetic
    }
    CHECK(solver.analyses() == 1);
    // A failed factorisation (indefinite) keeps the analysis; the shifted retry only refactorises.
    CHECK_THROWS_AS(solver.compute(grid(-0.5)), FactorizationError);
    CHECK_FALSE(solver.ready());
    solver.compute(grid(0.1));
    CHECK(solver.analyses() == 1);
    CHECK((solver.solve(b) - fresh(grid(0.1))).cwiseAbs().maxCoeff() == 0.0);
    // Another pattern (one more entry, an explicit zero) is analysed anew.
    solver.compute(grid(0.1, true));
    CHECK(solver.analyses() == 2);
    const Eigen::VectorXd x = solver.solve(b);
    CHECK((grid(0.1) * x - b).norm() <= 1e-10 * b.norm());
  }
}
