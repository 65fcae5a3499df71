// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Diffusion-reaction: spatial convergence orders against manufactured
// solutions, exact linear profiles, time orders of implicit Euler and
// Crank-Nicolson against exact solutions, conservation, and refusal of
// ill-posed problems.
#include <catch2/catch.hpp>

#include "structured_meshes.hpp"
#include "tessella/solvers/diffusion_reaction.hpp"
#include "tessella/solvers/errors.hpp"
#include "tessella/solvers/facets.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::solvers;
using tessella::test::boxMesh;
using tessella::test::cylinderStrip;
using tessella::test::rectangleMesh;

namespace {

const double kPi = std::acos(-1.0);

DiffusionOptions directOptions(TimeScheme scheme = TimeScheme::ImplicitEuler, MassType mass = MassType::Consistent) {
  DiffusionOptions o;
  o.scheme = scheme;
  o.mass = mass;
  o.linear.method = SolverMethod::Direct;
  return o;
}

double order(double coarse, double fine) { return std::log2(coarse / fine); }

}  // namespace

namespace {

// -lap u = f with u = e^x sin(pi y) [sin(pi z)] and Dirichlet data u on the
// whole boundary, on 3 refinements; checks the observed L2 and H1 orders.
void checkManufacturedOrders(int dim) {
  {
    // u = e^x sin(pi y) [sin(pi z)]: -lap u = (d-1) pi^2 u - u.
    auto u = [dim](const Eigen::Vector3d& x) {
      return std::exp(x.x()) * std::sin(kPi * x.y()) * (dim == 3 ? std::sin(kPi * x.z()) : 1.0);
    };
    auto grad_u = [dim](const Eigen::Vector3d& x) {
      const double sz = dim == 3 ? std::sin(kPi * x.z()) : 1.0;
      const double e = std::exp(x.x());
      return Eigen::Vector3d(e * std::sin(kPi * x.y()) * sz, kPi * e * std::cos(kPi * x.y()) * sz,
                             dim == 3 ? kPi * e * std::sin(kPi * x.y()) * std::cos(kPi * x.z()) : 0.0);
    };
    std::vector<double> l2, h1;
    for (int n : dim == 2 ? std::vector<int>{8, 16, 32} : std::vector<int>{4, 8, 16}) {
      const FeMesh m = dim == 2 ? rectangleMesh(n, n) : boxMesh(n, n, n);
      Species s;
      s.source = [&](const Eigen::Vector3d& x, double) { return ((dim - 1) * kPi * kPi - 1.0) * u(x); };
      s.dirichlet.push_back({boundaryFacets(m), 0.0, [&](const Eigen::Vector3d& x, double) { return u(x); }});
      DiffusionReaction solver(m, {s}, directOptions());
      solver.solveSteady();
      const test::ErrorNorms e = test::errorNorms(m, solver.state().col(0), u, grad_u);
      l2.push_back(std::sqrt(e.l2));
      h1.push_back(std::sqrt(e.h1));
    }
    for (std::size_t k = 1; k < l2.size(); ++k) {
      INFO("refinement " << k << ": L2 " << l2[k - 1] << " -> " << l2[k] << ", H1 " << h1[k - 1] << " -> " << h1[k]);
      CHECK(order(l2[k - 1], l2[k]) > 1.8);
      CHECK(order(h1[k - 1], h1[k]) > 0.9);
    }
    CHECK(order(l2[1], l2[2]) < 2.2);  // P1 cannot do better: the estimate is a real one
    CHECK(order(h1[1], h1[2]) < 1.2);
  }
}

}  // namespace

TEST_CASE("Manufactured -div(grad u) = f on the square: L2 order 2, H1 order 1", "[solvers][diffusion]") {
  checkManufacturedOrders(2);
}

TEST_CASE("Manufactured -div(grad u) = f on the cube: L2 order 2, H1 order 1", "[solvers][diffusion]") {
  checkManufacturedOrders(3);
}

TEST_CASE("Steady slab with Dirichlet ends is the exact (piecewise) linear profile", "[solvers][diffusion]") {
  for (int dim : {2, 3}) {
    INFO("dim " << dim);
    const FeMesh m = dim == 2 ? rectangleMesh(8, 3, 1.0, 0.5, true) : boxMesh(6, 2, 3, 1.0, 0.5, 0.7, true);
    const int right = 1;
    Species s;
    s.dirichlet.push_back({facetsOfWalls(m, {0}), 1.0, {}});
    s.dirichlet.push_back({facetsOfWalls(m, {right}), 0.0, {}});
    SECTION("uniform D: u = 1 - x") {
      s.diffusivity = Eigen::VectorXd::Constant(1, 2.5);
      DiffusionReaction solver(m, {s}, directOptions());
      const Eigen::VectorXd u = solver.solveSteady().col(0);
      CHECK((u - (Eigen::VectorXd::Ones(m.numNodes()) - m.nodes.col(0))).cwiseAbs().maxCoeff() < 1e-12);
    }
    SECTION("D = 1 | 4 in the two cells: flux continuity gives a kink at x = 1/2") {
      s.diffusivity = Eigen::Vector2d(1.0, 4.0);
      DiffusionReaction solver(m, {s}, directOptions());
      const Eigen::VectorXd u = solver.solveSteady().col(0);
      const double q = 1.0 / (0.5 / 1.0 + 0.5 / 4.0);  // flux through the slab
      double err = 0.0;
      for (int i = 0; i < m.numNodes(); ++i) {
        const double x = m.nodes(i, 0);
        const double exact = x <= 0.5 ? 1.0 - q * x : q * (1.0 - x) / 4.0;
        err = std::max(err, std::abs(u[i] - exact));
      }
      CHECK(err < 1e-12);
    }
    SECTION("Robin at the right end: -D u' = h (u - u_ext)") {
      s.dirichlet.pop_back();
      s.diffusivity = Eigen::VectorXd::Constant(1, 2.0);
      s.robin.push_back({facetsOfWalls(m, {right}), 3.0, 0.25});
      DiffusionReaction solver(m, {s}, directOptions());
      const Eigen::VectorXd u = solver.solveSteady().col(0);
      const double q = 3.0 * (1.0 - 0.25) / (1.0 + 3.0 / 2.0);
      CHECK((u - (Eigen::VectorXd::Ones(m.numNodes()) - q / 2.0 * m.nodes.col(0))).cwiseAbs().maxCoeff() < 1e-12);
    }
    SECTION("prescribed influx at the right end: D u' = g") {
      s.dirichlet.pop_back();
      s.dirichlet[0].value = 0.0;
      s.diffusivity = Eigen::VectorXd::Constant(1, 0.5);
      s.flux.push_back({facetsOfWalls(m, {right}), 2.0, {}});
      DiffusionReaction solver(m, {s}, directOptions());
      const Eigen::VectorXd u = solver.solveSteady().col(0);
      CHECK((u - 4.0 * m.nodes.col(0)).cwiseAbs().maxCoeff() < 1e-11);
    }
    SECTION("Dirichlet on the interior wall: left half linear, right half constant") {
      s.dirichlet.pop_back();
      s.dirichlet[0].value = 0.0;
      s.dirichlet.push_back({facetsOfWalls(m, {dim == 2 ? 4 : 6}), 1.0, {}});
      DiffusionReaction solver(m, {s}, directOptions());
      const Eigen::VectorXd u = solver.solveSteady().col(0);
      double err = 0.0;
      for (int i = 0; i < m.numNodes(); ++i) err = std::max(err, std::abs(u[i] - std::min(1.0, 2.0 * m.nodes(i, 0))));
      CHECK(err < 1e-12);
    }
  }
}

TEST_CASE("Steady diffusion on a curved sheet is linear in arc length", "[solvers][diffusion]") {
  const int n_theta = 10;
  const FeMesh m = cylinderStrip(n_theta, 4, 1.5, 2.0, 1.0);
  Species s;
  s.dirichlet.push_back({facetsOfWalls(m, {0}), 0.0, {}});
  s.dirichlet.push_back({facetsOfWalls(m, {1}), 1.0, {}});
  DiffusionReaction solver(m, {s}, directOptions());
  const Eigen::VectorXd u = solver.solveSteady().col(0);
  // The strip of planar rectangles unrolls isometrically onto a flat
  // rectangle, where the solution is linear: u = theta / angle at the nodes.
  double err = 0.0;
  for (int i = 0; i < m.numNodes(); ++i) err = std::max(err, std::abs(u[i] - (i % (n_theta + 1)) / double(n_theta)));
  CHECK(err < 1e-12);
}

TEST_CASE("Steady decay and production without boundary flux: u = p / k", "[solvers][diffusion]") {
  const FeMesh m = boxMesh(3, 3, 3, 1.0, 1.0, 1.0, false);
  Species s;
  s.decay = Eigen::VectorXd::Constant(1, 4.0);
  s.production = Eigen::VectorXd::Constant(1, 3.0);
  DiffusionReaction solver(m, {s}, directOptions());
  CHECK((solver.solveSteady().col(0).array() - 0.75).abs().maxCoeff() < 1e-13);
}

TEST_CASE("Time order: uniform decay-production-forcing problem", "[solvers][diffusion][time]") {
  // du/dt = -k u + p + cos t, zero flux, uniform data: the P1 solution stays
  // uniform, so the error is the time error alone.
  const double k = 2.0, p = 1.0, u0 = 0.3, T = 1.0;
  auto exact = [&](double t) {
    const double C = u0 - p / k - k / (k * k + 1);
    return p / k + (k * std::cos(t) + std::sin(t)) / (k * k + 1) + C * std::exp(-k * t);
  };
  const FeMesh m = rectangleMesh(3, 3);
  for (TimeScheme scheme : {TimeScheme::ImplicitEuler, TimeScheme::CrankNicolson}) {
    std::vector<double> err;
    for (int steps : {10, 20, 40}) {
      Species s;
      s.decay = Eigen::VectorXd::Constant(1, k);
      s.production = Eigen::VectorXd::Constant(1, p);
      s.source = [](const Eigen::Vector3d&, double t) { return std::cos(t); };
      DiffusionReaction solver(m, {s}, directOptions(scheme));
      solver.setState(0, Eigen::VectorXd::Constant(m.numNodes(), u0));
      solver.advance(T, T / steps);
      CHECK(solver.time() == Approx(T));
      err.push_back((solver.state().col(0).array() - exact(T)).abs().maxCoeff());
    }
    const double expected = scheme == TimeScheme::ImplicitEuler ? 1.0 : 2.0;
    INFO("errors " << err[0] << " " << err[1] << " " << err[2]);
    CHECK(order(err[0], err[1]) == Approx(expected).margin(0.1));
    CHECK(order(err[1], err[2]) == Approx(expected).margin(0.1));
  }
}

TEST_CASE("Time order: diffusion against the exact semi-discrete solution", "[solvers][diffusion][time]") {
  const FeMesh m = rectangleMesh(6, 5, 1.0, 0.8);
  const double T = 0.05;
  for (MassType mass : {MassType::Consistent, MassType::Lumped}) {
    // Exact solution of M u' = -K u: u(T) = V exp(-Lambda T) V^T M u0 with K V = M V Lambda.
    const Eigen::MatrixXd K(assembleStiffness(m)), M(assembleMass(m, mass));
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M);
    REQUIRE(eig.info() == Eigen::Success);
    Eigen::VectorXd u0(m.numNodes());
    for (int i = 0; i < m.numNodes(); ++i) u0[i] = std::cos(kPi * m.nodes(i, 0)) + m.nodes(i, 1) * m.nodes(i, 1);
    const Eigen::MatrixXd& V = eig.eigenvectors();
    const Eigen::VectorXd uT = V * ((-T * eig.eigenvalues()).array().exp() * (V.transpose() * M * u0).array()).matrix();
    for (TimeScheme scheme : {TimeScheme::ImplicitEuler, TimeScheme::CrankNicolson}) {
      std::vector<double> err;
      for (int steps : {8, 16, 32}) {
        DiffusionReaction solver(m, {Species{}}, directOptions(scheme, mass));
        solver.setState(0, u0);
        solver.advance(T, T / steps);
        err.push_back((solver.state().col(0) - uT).cwiseAbs().maxCoeff());
      }
      const double expected = scheme == TimeScheme::ImplicitEuler ? 1.0 : 2.0;
      INFO("mass " << int(mass) << " scheme " << int(scheme) << " errors " << err[0] << " " << err[1] << " " << err[2]);
      CHECK(order(err[1], err[2]) == Approx(expected).margin(0.15));
    }
  }
}

TEST_CASE("Transient diffusion of a cosine mode converges to exp(-pi^2 D t) cos(pi x)", "[solvers][diffusion][time]") {
  // Zero-flux slab: u = exp(-pi^2 D t) cos(pi x) solves the PDE exactly. With
  // small Crank-Nicolson steps the error is the spatial one: order 2 in L2.
  const double D = 0.5, T = 0.2;
  std::vector<double> err;
  for (int nx : {8, 16, 32}) {
    const FeMesh m = rectangleMesh(nx, nx / 8, 1.0, 0.125);  // square cells at every level
    Species s;
    s.diffusivity = Eigen::VectorXd::Constant(1, D);
    DiffusionReaction solver(m, {s}, directOptions(TimeScheme::CrankNicolson));
    solver.setState(0, [](const Eigen::Vector3d& x, double) { return std::cos(kPi * x.x()); });
    solver.advance(T, T / 200);
    const double decay = std::exp(-kPi * kPi * D * T);
    const test::ErrorNorms e = test::errorNorms(
        m, solver.state().col(0), [&](const Eigen::Vector3d& x) { return decay * std::cos(kPi * x.x()); },
        [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(-kPi * decay * std::sin(kPi * x.x()), 0.0, 0.0); });
    err.push_back(std::sqrt(e.l2));
  }
  INFO("errors " << err[0] << " " << err[1] << " " << err[2]);
  CHECK(err[2] < 2e-3);
  CHECK(order(err[1], err[2]) == Approx(2.0).margin(0.2));
}

TEST_CASE("Nonlinear reaction: semi-implicit orders and a conserved coupled pair", "[solvers][diffusion][reaction]") {
  const FeMesh m = rectangleMesh(3, 2);
  SECTION("du/dt = -u^2, u(0) = 1: u = 1 / (1 + t)") {
    for (TimeScheme scheme : {TimeScheme::ImplicitEuler, TimeScheme::CrankNicolson}) {
      std::vector<double> err;
      for (int steps : {20, 40, 80}) {
        DiffusionReaction solver(m, {Species{}}, directOptions(scheme));
        solver.setReaction([](std::span<const double> u, std::span<double> r) { r[0] = -u[0] * u[0]; });
        solver.setState(0, Eigen::VectorXd::Ones(m.numNodes()));
        solver.advance(1.0, 1.0 / steps);
        err.push_back((solver.state().col(0).array() - 0.5).abs().maxCoeff());
      }
      const double expected = scheme == TimeScheme::ImplicitEuler ? 1.0 : 2.0;
      INFO("errors " << err[0] << " " << err[1] << " " << err[2]);
      CHECK(order(err[1], err[2]) == Approx(expected).margin(0.15));
    }
  }
  SECTION("A -> B conversion with diffusion: A + B conserved, A decays like exp(-c t)") {
    // Names moved in: GCC 12 warns falsely (-Wrestrict) on assigning a literal here.
    Species a, b;
    a.name = std::string(1, 'A');
    b.name = std::string(1, 'B');
    b.diffusivity = Eigen::VectorXd::Constant(1, 0.1);
    DiffusionReaction solver(m, {a, b}, directOptions(TimeScheme::CrankNicolson));
    const double c = 1.5;
    solver.setReaction([c](std::span<const double> u, std::span<double> r) {
      r[0] = -c * u[0];
      r[1] = c * u[0];
    });
    solver.setState(0, [](const Eigen::Vector3d& x, double) { return 1.0 + 0.5 * std::cos(kPi * x.x()); });
    const double total0 = solver.totalAmount(0) + solver.totalAmount(1);
    const double a0 = solver.totalAmount(0);
    solver.advance(1.0, 1.0 / 200);
    CHECK(solver.totalAmount(0) + solver.totalAmount(1) == Approx(total0).epsilon(1e-13));
    CHECK(solver.totalAmount(0) == Approx(a0 * std::exp(-c)).epsilon(1e-4));
  }
  SECTION("steady state with a nonlinear reaction by Picard iteration") {
    // Uniform: 0 = 1 - u - 0.2 u^3 (Picard map contracts: |0.6 u^2| < 1 near the root).
    Species s;
    s.production = Eigen::VectorXd::Constant(1, 1.0);
    s.decay = Eigen::VectorXd::Constant(1, 1.0);
    DiffusionReaction solver(m, {s}, directOptions());
    solver.setReaction([](std::span<const double> u, std::span<double> r) { r[0] = -0.2 * u[0] * u[0] * u[0]; });
    const Eigen::VectorXd u = solver.solveSteady().col(0);
    CHECK((u.array() - u[0]).abs().maxCoeff() < 1e-12);
    CHECK(1.0 - u[0] - 0.2 * u[0] * u[0] * u[0] == Approx(0.0).margin(1e-9));
    CHECK(u[0] > 0.5);
    CHECK(u[0] < 1.0);
  }
}

TEST_CASE("Zero-flux diffusion conserves the total amount to round-off", "[solvers][diffusion][conservation]") {
  const FeMesh m = rectangleMesh(10, 10, 1.0, 1.0, true);
  for (TimeScheme scheme : {TimeScheme::ImplicitEuler, TimeScheme::CrankNicolson})
    for (MassType mass : {MassType::Consistent, MassType::Lumped}) {
      Species s;
      s.diffusivity = Eigen::Vector2d(1.0, 0.1);
      DiffusionReaction solver(m, {s}, directOptions(scheme, mass));
      solver.setState(0, [](const Eigen::Vector3d& x, double) { return x.x() * x.x() + 0.5 * std::sin(3 * x.y()); });
      const double total0 = solver.totalAmount(0);
      const Eigen::VectorXd u0 = solver.state().col(0);
      solver.advance(0.3, 0.01);
      CHECK(std::abs(solver.totalAmount(0) - total0) <= 1e-13 * std::abs(total0));
      CHECK((solver.state().col(0) - u0).norm() > 0.1);  // it did diffuse
    }
  SECTION("a source in one cell adds exactly production x cell area x time") {
    Species s;
    s.production = Eigen::Vector2d(0.0, 2.0);  // only cell 1 (area 1/2) produces
    DiffusionReaction solver(m, {s}, directOptions(TimeScheme::CrankNicolson));
    solver.advance(0.75, 0.05);
    CHECK(solver.totalAmount(0) == Approx(2.0 * 0.5 * 0.75).epsilon(1e-13));
    CHECK(solver.state()(0, 0) < solver.state()(m.numNodes() - 1, 0));  // more where it is produced
  }
}

TEST_CASE("Ill-posed diffusion problems raise clear errors", "[solvers][diffusion][errors]") {
  const FeMesh m = rectangleMesh(4, 4, 1.0, 1.0, true);
  Species s;
  s.diffusivity = Eigen::Vector2d(1.0, -0.5);
  CHECK_THROWS_AS(DiffusionReaction(m, {s}), InvalidProblemError);
  s.diffusivity = Eigen::VectorXd::Constant(3, 1.0);
  s.diffusivity[0] = std::nan("");
  CHECK_THROWS_AS(DiffusionReaction(m, {s}), InvalidProblemError);

  Species neumann;
  neumann.name = "auxin";
  neumann.flux.push_back({boundaryFacets(m), 0.1, {}});
  DiffusionReaction solver(m, {neumann}, directOptions());
  try {
    solver.solveSteady();
    FAIL("expected InvalidProblemError");
  } catch (const InvalidProblemError& e) {
    const std::string what = e.what();
    CHECK(what.find("auxin") != std::string::npos);
    CHECK(what.find("singular") != std::string::npos);
  }
  CHECK_NOTHROW(solver.step(0.1));  // the same problem is fine in time

  Species robin;
  robin.robin.push_back({boundaryFacets(m), -1.0, 0.0});
  CHECK_THROWS_AS(DiffusionReaction(m, {robin}), InvalidProblemError);
  Species bad_facet;
  bad_facet.dirichlet.push_back({{m.numWallFacets() + 3}, 0.0, {}});
  CHECK_THROWS_AS(DiffusionReaction(m, {bad_facet}), InvalidProblemError);
  CHECK_THROWS_AS(DiffusionReaction(m, {}), InvalidProblemError);
  CHECK_THROWS_AS(solver.step(0.0), InvalidProblemError);
}
