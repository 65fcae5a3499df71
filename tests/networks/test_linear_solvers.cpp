// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "network_fixtures.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_integrator.hpp"
#include "tessella/tissue/geometry.hpp"

using namespace tessella;
using namespace tessella::networks;

namespace {

// Three species on a hexagonal grid: auxin with up-the-gradient PIN and passive exchange, A induced by
// auxin (Hill), B repressed by A (Hill); the model of bench/network_bench.cpp.
NetworkModel threeSpecies() {
  NetworkModel m;
  m.parameters = {{"p", 0.5}, {"d", 0.05}, {"kA", 1.0}, {"KA", 10.0}, {"dA", 0.1},
                  {"kB", 1.0}, {"KB", 5.0}, {"dB", 0.1}};
  m.species.push_back({"auxin", "p - d * auxin", 0.05});
  m.species.push_back({"A", "kA * auxin^2 / (KA^2 + auxin^2) - dA * A", 0.01});
  m.species.push_back({"B", "kB / (1 + (A / KB)^2) - dB * B", 0.0});
  m.pin.species = "auxin";
  m.pin.base = 2.0;
  return m;
}

std::vector<double> noisyStart(const NetworkGraph& g, std::size_t S, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(0.0, 0.5);
  std::vector<double> y(g.numCells() * S);
  for (std::size_t c = 0; c < g.numCells(); ++c)
    for (std::size_t s = 0; s < S; ++s) y[c * S + s] = (s == 0 ? 10.0 + noise(rng) : 1.0) * g.measure[c];
  return y;
}

std::vector<double> integrate(NetworkSystem& system, std::vector<double> y, double t1, double rtol, double atol,
                              LinearSolver solver) {
  IntegratorOptions o;
  o.relative_tolerance = rtol;
  o.absolute_tolerance = atol;
  o.linear_solver = solver;
  NetworkIntegrator integrator(system, o);
  integrator.advance(y, 0.0, t1);
  return y;
}

double maxError(const std::vector<double>& a, const std::vector<double>& reference) {
  double e = 0;
  for (std::size_t k = 0; k < a.size(); ++k) e = std::max(e, std::abs(a[k] - reference[k]) / std::abs(reference[k]));
  return e;
}

}  // namespace

TEST_CASE("GMRES with the block-Jacobi preconditioner is as accurate as KLU", "[networks]") {
  GeometryCache geometry;
  const NetworkGraph g = networkGraph(hexagonalGrid(12, 12), geometry, {});
  const NetworkModel model = threeSpecies();
  const std::vector<double> y0 = noisyStart(g, 3, 11);
  const double t1 = 10.0;  // auxin moves into peaks: PIN and reactions both act
  NetworkSystem exact(model, g, JacobianKind::Exact);
  // The reference: tolerances 1e4 times tighter than the runs compared with it.
  const std::vector<double> reference = integrate(exact, y0, t1, 1e-10, 1e-13, LinearSolver::Klu);
  const std::vector<double> klu = integrate(exact, y0, t1, 1e-6, 1e-9, LinearSolver::Klu);
  const double klu_error = maxError(klu, reference);
  for (JacobianKind kind : {JacobianKind::Exact, JacobianKind::Neighbours}) {
    NetworkSystem system(model, g, kind);
    const std::vector<double> gmres = integrate(system, y0, t1, 1e-6, 1e-9, LinearSolver::Gmres);
    const double gmres_error = maxError(gmres, reference);
    INFO("KLU error " << klu_error << ", GMRES error " << gmres_error);
    // The same tolerances give errors of the same order (the global error of either is some 1e-4 here).
    CHECK(gmres_error < 3 * klu_error);
    // Tight tolerances: the two solvers converge to the same solution.
    const std::vector<double> tight = integrate(system, y0, t1, 1e-10, 1e-13, LinearSolver::Gmres);
    CHECK(maxError(tight, reference) < 1e-7);
  }
}

TEST_CASE("GMRES keeps the amounts of transport", "[networks]") {
  GeometryCache geometry;
  const NetworkGraph g = networkGraph(hexagonalGrid(10, 10), geometry, {});
  NetworkModel m = testing::oneSpecies("auxin", 0.05);
  m.pin.species = "auxin";
  m.pin.base = 2.0;
  NetworkSystem system(m, g, JacobianKind::Neighbours);
  const std::vector<double> y0 = noisyStart(g, 1, 3);
  const std::vector<double> y = integrate(system, y0, 0.0 + 20.0, 1e-6, 1e-9, LinearSolver::Gmres);
  const double before = system.totalAmount(y0, 0), after = system.totalAmount(y, 0);
  INFO("relative drift " << std::abs(after - before) / before);
  CHECK(std::abs(after - before) <= 1e-12 * before);
}

TEST_CASE("The integrator's counters and timers add up", "[networks]") {
  GeometryCache geometry;
  const NetworkGraph g = networkGraph(hexagonalGrid(6, 6), geometry, {});
  NetworkSystem system(threeSpecies(), g, JacobianKind::Neighbours);
  for (LinearSolver solver : {LinearSolver::Klu, LinearSolver::Gmres}) {
    IntegratorOptions o;
    o.linear_solver = solver;
    o.timers = true;
    NetworkIntegrator integrator(system, o);
    std::vector<double> y = noisyStart(g, 3, 5);
    integrator.advance(y, 0.0, 2.0);
    const IntegratorStatistics& s = integrator.statistics();
    CHECK(s.linear_setups >= 1);
    CHECK(s.jacobian_evaluations >= 1);
    CHECK(s.jacobian_evaluations <= s.linear_setups);
    CHECK(s.linear_solves >= s.linear_setups);
    CHECK((solver == LinearSolver::Gmres) == (s.linear_iterations > 0));
    CHECK(s.rhs_seconds > 0);
    CHECK(s.setup_seconds > 0);
    CHECK(s.solve_seconds > 0);
  }
  IntegratorOptions bad;
  bad.setup_frequency = -1;
  CHECK_THROWS_AS(NetworkIntegrator(system, bad), InputError);
  CHECK(linearSolvers().parse("gmres") == LinearSolver::Gmres);
}

TEST_CASE("One and two threads give bit-identical right-hand sides, Jacobians and runs", "[networks]") {
  GeometryCache geometry;
  // 64 x 64 = 4096 cells: enough for the cell loops to be split over threads; 210 x 210 (132300 unknowns):
  // enough for the vector operations too.
  for (std::size_t side : {64, 210}) {
    const NetworkGraph g = networkGraph(hexagonalGrid(side, side), geometry, {});
    NetworkSystem one(threeSpecies(), g, JacobianKind::Neighbours), two(threeSpecies(), g, JacobianKind::Neighbours);
    one.setThreads(1);
    two.setThreads(2);
    const std::vector<double> y0 = noisyStart(g, 3, 7);
    if (side == 64) {
      std::vector<double> f1(one.size()), f2(two.size());
      one.rhs(0.5, y0, f1);
      two.rhs(0.5, y0, f2);
      CHECK(f1 == f2);
      CsrMatrix J1, J2;
      one.jacobian(0.5, y0, J1);
      two.jacobian(0.5, y0, J2);
      CHECK(J1.value == J2.value);
    }
    const double t1 = side == 64 ? 2.0 : 0.05;
    std::vector<std::vector<double>> runs;
    for (int threads : {1, 2}) {
      IntegratorOptions o;
      o.linear_solver = LinearSolver::Gmres;
      o.threads = threads;
      o.adapt_threads = false;  // two threads even on a loaded machine
      NetworkIntegrator integrator(threads == 1 ? one : two, o);
      std::vector<double> y = y0;
      integrator.advance(y, 0.0, t1);
      CHECK(integrator.statistics().steps > 5);
      runs.push_back(y);
    }
    CHECK(runs[0] == runs[1]);
  }
  IntegratorOptions bad;
  bad.threads = -1;
  GeometryCache small_geometry;
  NetworkSystem small(threeSpecies(), networkGraph(hexagonalGrid(3, 3), small_geometry, {}));
  CHECK_THROWS_AS(NetworkIntegrator(small, bad), InputError);
}
