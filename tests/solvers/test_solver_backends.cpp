// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Optional linear-solver back-ends (CHOLMOD, hypre BoomerAMG + CG): each one,
// when built, solves Poisson problems to the analytic answer and agrees with
// Eigen's direct solver; a back-end that is not built is a clear error.
#include <catch2/catch.hpp>

#include "structured_meshes.hpp"
#include "tessella/solvers/assembly.hpp"
#include "tessella/solvers/diffusion_reaction.hpp"
#include "tessella/solvers/errors.hpp"
#include "tessella/solvers/facets.hpp"
#include "tessella/solvers/linear_solver.hpp"

#include <cmath>
#include <string>
#include <vector>

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::solvers;
using tessella::test::boxMesh;
using tessella::test::rectangleMesh;

namespace {

const double kPi = std::acos(-1.0);

// Steady -lap u = f with Dirichlet data u on the whole boundary.
template <typename U, typename F>
Eigen::VectorXd solvePoisson(const FeMesh& m, SolverMethod method, U&& u, F&& f, SolveReport* report = nullptr,
                             double strong_threshold = 0.5) {
  Species s;
  s.source = [&](const Eigen::Vector3d& x, double) { return f(x); };
  s.dirichlet.push_back({boundaryFacets(m), 0.0, [&](const Eigen::Vector3d& x, double) { return u(x); }});
  DiffusionOptions o;
  o.linear.method = method;
  o.linear.tolerance = 1e-12;
  o.linear.amg_strong_threshold = strong_threshold;
  DiffusionReaction solver(m, {s}, o);
  solver.solveSteady();
  if (report) *report = solver.lastReport();
  return solver.state().col(0);
}

const std::vector<SolverMethod> kBackends = {SolverMethod::Cholmod, SolverMethod::AmgCG};

}  // namespace

TEST_CASE("Every built back-end reproduces a linear solution exactly (P1 is exact for it)", "[solvers][backends]") {
  auto u = [](const Eigen::Vector3d& x) { return 1.0 + 2.0 * x.x() - 3.0 * x.y() + 0.5 * x.z(); };
  auto zero = [](const Eigen::Vector3d&) { return 0.0; };
  for (int dim : {2, 3}) {
    const FeMesh m = dim == 2 ? rectangleMesh(24, 20, 1.0, 0.8) : boxMesh(10, 9, 8);
    for (SolverMethod method : kBackends) {
      if (!solverAvailable(method)) continue;
      INFO(toString(method) << ", dim " << dim);
      SolveReport r;
      const Eigen::VectorXd uh = solvePoisson(m, method, u, zero, &r);
      double err = 0.0;
      for (int i = 0; i < m.numNodes(); ++i) err = std::max(err, std::abs(uh[i] - u(m.nodes.row(i).transpose())));
      CHECK(err < 1e-9);
      CHECK(r.method == method);
      CHECK(r.relative_residual <= 1e-11);
      if (method == SolverMethod::AmgCG) CHECK(r.iterations > 0);
      if (method == SolverMethod::Cholmod) CHECK(r.iterations == 0);
    }
  }
}

TEST_CASE("Back-ends agree with Eigen's direct solver on a manufactured Poisson problem", "[solvers][backends]") {
  // u = sin(pi x) sin(pi y) sin(pi z): -lap u = 3 pi^2 u; u = 0 on the boundary.
  auto u = [](const Eigen::Vector3d& x) { return std::sin(kPi * x.x()) * std::sin(kPi * x.y()) * std::sin(kPi * x.z()); };
  auto f = [&](const Eigen::Vector3d& x) { return 3.0 * kPi * kPi * u(x); };
  const FeMesh m = boxMesh(14, 14, 14);
  const Eigen::VectorXd ref = solvePoisson(m, SolverMethod::Direct, u, f);
  // The discretisation error itself (nodal max), to know what "same answer" means.
  double disc = 0.0;
  for (int i = 0; i < m.numNodes(); ++i) disc = std::max(disc, std::abs(ref[i] - u(m.nodes.row(i).transpose())));
  CHECK(disc < 0.05);
  for (SolverMethod method : kBackends) {
    if (!solverAvailable(method)) continue;
    INFO(toString(method));
    const Eigen::VectorXd uh = solvePoisson(m, method, u, f);
    CHECK((uh - ref).cwiseAbs().maxCoeff() < 1e-9);
  }
}

TEST_CASE("BoomerAMG + CG iterations barely grow with the mesh", "[solvers][backends]") {
  if (!solverAvailable(SolverMethod::AmgCG)) return;
  auto u = [](const Eigen::Vector3d& x) { return x.x() * x.x() + x.y(); };
  auto f = [](const Eigen::Vector3d&) { return -2.0; };  // P1 is not exact for x^2: a real solve
  std::vector<int> its;
  for (int n : {8, 16, 32}) {
    SolveReport r;
    solvePoisson(boxMesh(n, n, n), SolverMethod::AmgCG, u, f, &r);
    its.push_back(r.iterations);
  }
  INFO("iterations " << its[0] << ", " << its[1] << ", " << its[2]);
  // Jacobi-CG iterations double with each refinement; AMG's stay nearly flat.
  CHECK(its[2] <= 25);
  CHECK(its[2] <= 2 * its[0]);
}

TEST_CASE("CHOLMOD refuses singular and indefinite matrices", "[solvers][backends]") {
  if (!solverAvailable(SolverMethod::Cholmod)) return;
  LinearSolverOptions opt;
  opt.method = SolverMethod::Cholmod;
  LinearSolver solver(opt);
  // Pure-Neumann Laplacian of a 1D chain: singular (rows sum to zero).
  const int n = 60;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i + 1 < n; ++i) {
    t.emplace_back(i, i, 1.0), t.emplace_back(i + 1, i + 1, 1.0);
    t.emplace_back(i, i + 1, -1.0), t.emplace_back(i + 1, i, -1.0);
  }
  SparseMatrix L(n, n);
  L.setFromTriplets(t.begin(), t.end());
  CHECK_THROWS_AS(solver.compute(L), FactorizationError);
  SparseMatrix indefinite(3, 3);
  indefinite.insert(0, 0) = 1.0;
  indefinite.insert(1, 1) = -1.0;
  indefinite.insert(2, 2) = 2.0;
  CHECK_THROWS_AS(solver.compute(indefinite), FactorizationError);
}

TEST_CASE("AmgCG reports non-convergence with iterations and residual", "[solvers][backends]") {
  if (!solverAvailable(SolverMethod::AmgCG)) return;
  LinearSolverOptions opt;
  opt.method = SolverMethod::AmgCG;
  opt.max_iterations = 1;
  opt.tolerance = 1e-14;
  const FeMesh m = boxMesh(12, 12, 12);
  const SparseMatrix K = assembleStiffness(m);
  SparseMatrix A = K;  // + mass-like shift: SPD without boundary conditions
  for (int i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += 1e-3;
  LinearSolver solver(opt);
  solver.compute(A);
  try {
    solver.solve(Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 1.0));
    FAIL("expected ConvergenceError");
  } catch (const ConvergenceError& e) {
    CHECK(std::string(e.what()).find("BoomerAMG did not converge in 1 iterations") != std::string::npos);
  }
}

TEST_CASE("A back-end that is not built is a clear error; Auto never picks one", "[solvers][backends]") {
  for (SolverMethod method : kBackends) {
    LinearSolverOptions opt;
    opt.method = method;
    if (solverAvailable(method)) {
      CHECK_NOTHROW(LinearSolver(opt));
    } else {
      try {
        LinearSolver solver(opt);
        FAIL("expected InvalidProblemError");
      } catch (const InvalidProblemError& e) {
        CHECK(std::string(e.what()).find("not built") != std::string::npos);
        CHECK(std::string(e.what()).find("TESSELLA_WITH_") != std::string::npos);
      }
    }
  }
  LinearSolverOptions opt;
  opt.auto_direct_max_unknowns = 10;
  LinearSolver large(opt);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 50; ++i) t.emplace_back(i, i, 2.0 + i);
  SparseMatrix D(50, 50);
  D.setFromTriplets(t.begin(), t.end());
  large.compute(D);
  CHECK(large.method() ==
        (solverAvailable(SolverMethod::AmgCG) ? SolverMethod::AmgCG : SolverMethod::ConjugateGradient));
}
