// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The equilibrium solver: a pressurised ring of wall springs against its
// closed form, Newton's behaviour on Voronoi tissues (energy decreasing,
// quadratic convergence, shifts on indefinite tangents), errors, threads.
#include <catch2/catch.hpp>

#include "ring.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/mechanics/boundary_conditions.hpp"
#include "tessella/mechanics/errors.hpp"
#include "tessella/mechanics/planar_dofs.hpp"
#include "tessella/mechanics/turgor_growth_step.hpp"
#include "tessella/mechanics/wall_spring_model.hpp"
#include "tessella/mechanics/wall_state.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

#include <omp.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace tessella;
using namespace tessella::mechanics;

namespace {

// The ring's model: N springs of rest length L0, stiffness S, pressure P.
WallSpringModel ringModel(const Tissue& ring, double L0, double S, double P) {
  std::vector<double> rest(ring.slots(1), L0), stiff(ring.slots(1), S), pressure(ring.cellSlots(), P);
  return WallSpringModel::fromTissue(ring, rest, stiff, pressure);
}

Tissue voronoi(std::size_t cells, std::uint64_t seed) {
  Rectangle domain{Vec3(0, 0, 0), Vec3(6, 4, 0)};
  return voronoiTissue(randomSeeds(domain, cells, seed), domain, VoronoiOptions{.lloyd_iterations = 2});
}

}  // namespace

TEST_CASE("equilibrium: a pressurised ring of N wall springs has side L0 / (1 - P L0 / (2 S tan(pi/N)))",
          "[mechanics]") {
  for (int n : {3, 5, 6, 12}) {
    for (double start : {1.0, 0.75}) {  // 0.75: walls start compressed (indefinite tangent)
      CAPTURE(n, start);
      const double L0 = 0.7, S = 2.0, P = 0.9;
      const Tissue ring = test::ringTissue(n, start * L0);
      const WallSpringModel model = ringModel(ring, L0, S, P);
      Eigen::VectorXd x = planarDofs(ring);
      FixedDofs fixed = deadSlotMask(ring);
      pinPoint(ring, ring.position(VertexId(0)), fixed);
      EquilibriumOptions options;
      options.relative_tolerance = 1e-14;
      const EquilibriumReport report = solveEquilibrium(model, x, fixed, options);
      const double L = test::ringSide(n, P, S, L0);
      REQUIRE(test::ringLoad(n, P, S, L0) < 1.0);
      for (std::size_t i = 0; i < model.springs().size(); ++i) CHECK(std::abs(model.length(x, i) - L) < 1e-10 * L);
      // Circumradius from the centroid and the tension from force balance.
      Eigen::Vector2d centre = Eigen::Vector2d::Zero();
      for (int i = 0; i < n; ++i) centre += x.segment<2>(2 * i) / n;
      const double R = L / (2 * std::sin(std::numbers::pi / n));
      for (int i = 0; i < n; ++i) CHECK(std::abs((x.segment<2>(2 * i) - centre).norm() - R) < 1e-10 * R);
      CHECK(model.tension(x, 0) == Approx(P * L / (2 * std::tan(std::numbers::pi / n))).epsilon(1e-10));
      CHECK(report.residual <= report.tolerance);
      // The tangent's pattern is analysed once; every later factorisation reuses it.
      CHECK(report.linear_solves >= report.iterations);
      CHECK(report.analyses == 1);
      if (start < 1.0) {
        REQUIRE(!report.shifts.empty());
        CHECK(report.shifts.front() > 0.0);  // the compressed start needed a shift
        CHECK(report.linear_solves > 1);
        CHECK(report.shifts.back() == 0.0);  // pure Newton at the end
      }
    }
  }
}

TEST_CASE("equilibrium: a Voronoi tissue under turgor converges quadratically with decreasing energy",
          "[mechanics]") {
  Tissue tissue = voronoi(40, 3);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> rest(tissue.slots(1), 0.0), stiff(tissue.slots(1), 1.0), pressure(tissue.cellSlots(), 0.0);
  for (EdgeId e : tissue.edges()) rest[e.index()] = edgeLength(tissue, e);
  for (CellId c : tissue.cells()) pressure[c.index()] = 0.1 + 0.1 * u(rng);  // uneven: interior walls load too
  const WallSpringModel model = WallSpringModel::fromTissue(tissue, rest, stiff, pressure);
  Eigen::VectorXd x = planarDofs(tissue);
  FixedDofs fixed = deadSlotMask(tissue);
  pinPoint(tissue, Vec3(3, 2, 0), fixed);
  EquilibriumOptions options;
  options.relative_tolerance = 1e-13;
  const EquilibriumReport r = solveEquilibrium(model, x, fixed, options);
  REQUIRE(r.iterations >= 3);
  REQUIRE(r.residuals.size() == static_cast<std::size_t>(r.iterations) + 1);
  // Energy decreases at every accepted step (up to round-off of the energy's terms).
  const double noise = 1e-13 * model.energyScale(x);
  for (std::size_t k = 1; k < r.energies.size(); ++k) CHECK(r.energies[k] <= r.energies[k - 1] + noise);
  CHECK(r.energies.back() < r.energies.front() - 1e-3 * std::abs(r.energies.front()));
  // Quadratic convergence: near the solution (relative residual < 1e-4) each
  // step squares the relative residual, up to a constant and round-off, and
  // the Newton step is taken whole and unshifted. (Further out the constant
  // is larger: a Voronoi tissue has soft modes, walls at small strain.)
  const double s = r.force_scale;
  for (std::size_t k = 0; k < r.residuals.size(); ++k)
    UNSCOPED_INFO("relative residual " << k << ": " << r.residuals[k] / s << ", energy " << r.energies[k]);
  int near = 0, above_roundoff = 0;
  for (std::size_t k = 0; k + 1 < r.residuals.size(); ++k) {
    const double rk = r.residuals[k] / s, rn = r.residuals[k + 1] / s;
    if (rk < 1e-4) {
      ++near;
      if (rn > 1e-13) ++above_roundoff;
      CAPTURE(k, rk, rn);
      CHECK(rn <= 10.0 * rk * rk + 1e-14);
      CHECK(r.step_lengths[k] == 1.0);
      CHECK(r.shifts[k] == 0.0);
    }
  }
  CHECK(near >= 2);
  CHECK(above_roundoff >= 1);  // at least one squaring seen above round-off
  // The solution is an equilibrium: gradient on free dofs, positive areas.
  Eigen::VectorXd g;
  model.gradient(x, g);
  for (Eigen::Index i = 0; i < g.size(); ++i)
    if (!fixed[static_cast<std::size_t>(i)]) CHECK(std::abs(g[i]) <= 1e-12 * s);
  for (std::size_t j = 0; j < model.cells().size(); ++j) CHECK(model.area(x, j) > 0.0);
}

TEST_CASE("equilibrium: the pinned point and its rotation lock stay put", "[mechanics]") {
  Tissue tissue = voronoi(20, 9);
  TurgorGrowthParams params;
  params.pressure = 0.2;
  params.supports.pin = true;
  params.supports.pin_point = Vec3(1, 1, 0);
  FixedDofs fixed = deadSlotMask(tissue);
  const PinnedPoint pin = pinPoint(tissue, params.supports.pin_point, fixed);
  const Vec3 p0 = tissue.position(pin.vertex), p1 = tissue.position(pin.rotation_lock);
  const double area_before = totalMeasure(tissue);
  const TurgorStepReport report = turgorGrowthStep(tissue, params, 0.0);
  CHECK(tissue.position(pin.vertex) == p0);
  CHECK(tissue.position(pin.rotation_lock)[pin.lock_component] == p1[pin.lock_component]);
  CHECK(totalMeasure(tissue) > area_before);  // turgor inflates the tissue
  CHECK(report.max_strain > 0.0);
  CHECK(validate(tissue).ok);
}

TEST_CASE("equilibrium: non-convergence throws naming the context and restores the positions", "[mechanics]") {
  const Tissue ring = test::ringTissue(8, 1.0);
  const WallSpringModel model = ringModel(ring, 1.0, 1.0, 0.5);
  Eigen::VectorXd x = planarDofs(ring);
  const Eigen::VectorXd before = x;
  FixedDofs fixed = deadSlotMask(ring);
  pinPoint(ring, Vec3::Zero(), fixed);
  EquilibriumOptions options;
  options.max_iterations = 1;
  options.context = "step 7, time 0.35";
  try {
    solveEquilibrium(model, x, fixed, options);
    FAIL("no error");
  } catch (const EquilibriumError& e) {
    CHECK_THAT(e.what(), Catch::Contains("step 7, time 0.35") && Catch::Contains("residual") &&
                             Catch::Contains("1 Newton iterations"));
    CHECK(e.residual() > 0.0);
  }
  CHECK(x == before);
  // Beyond the ring's limit load (a >= 1) there is no equilibrium at all.
  const WallSpringModel burst = ringModel(ring, 1.0, 1.0, 2.0 * 1.0 * std::tan(std::numbers::pi / 8) * 1.5);
  options.max_iterations = 30;
  CHECK_THROWS_AS(solveEquilibrium(burst, x, fixed, options), EquilibriumError);
  CHECK(x == before);
  options.armijo = 0.7;
  CHECK_THROWS_WITH(solveEquilibrium(model, x, fixed, options), Catch::Contains("armijo"));
}

TEST_CASE("equilibrium: thread counts 1 and 2 give bit-identical positions", "[mechanics]") {
  auto run = [](int threads) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    Tissue tissue = voronoi(60, 21);
    TurgorGrowthParams params;
    params.pressure = 0.15;
    params.growth.extensibility = 1.0;
    params.supports.pin = true;
    params.supports.pin_point = Vec3(3, 2, 0);
    for (int step = 0; step < 3; ++step) turgorGrowthStep(tissue, params, 0.1);
    omp_set_num_threads(saved);
    return std::vector<Vec3>(tissue.positions().begin(), tissue.positions().end());
  };
  CHECK(run(1) == run(2));
}

// `auto` (the default) factorises tangents of at least auto_cholmod_unknowns free dofs with CHOLMOD
// when it is built, smaller ones with Eigen's LDL^T (the same arithmetic as `ldlt`); both reach the
// same equilibrium within Newton's tolerance, and CHOLMOD's is the same bit for bit with 1 and 2
// threads.
TEST_CASE(
    "equilibrium: the default tangent solver is CHOLMOD from a size, LDL^T below; same equilibrium",
    "[mechanics]") {
  Tissue tissue = voronoi(40, 3);
  std::vector<double> rest(tissue.slots(1), 0.0), stiff(tissue.slots(1), 1.0),
      pressure(tissue.cellSlots(), 0.15);
  for (EdgeId e : tissue.edges()) rest[e.index()] = 0.95 * edgeLength(tissue, e);
  const WallSpringModel model = WallSpringModel::fromTissue(tissue, rest, stiff, pressure);
  FixedDofs fixed = deadSlotMask(tissue);
  pinPoint(tissue, Vec3(3, 2, 0), fixed);
  auto solve = [&](solvers::SolverMethod method, Eigen::Index from, int threads,
                   EquilibriumReport* report) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    EquilibriumOptions options;
    options.relative_tolerance = 1e-12;
    options.linear.method = method;
    options.auto_cholmod_unknowns = from;
    Eigen::VectorXd x = planarDofs(tissue);
    *report = solveEquilibrium(model, x, fixed, options);
    omp_set_num_threads(saved);
    return x;
  };
  EquilibriumReport small, ldlt, large, large2;
  const Eigen::VectorXd by_default = solve(solvers::SolverMethod::Auto, 5000, 2, &small);
  const Eigen::VectorXd direct = solve(solvers::SolverMethod::Direct, 5000, 2, &ldlt);
  CHECK(small.linear_method ==
        solvers::SolverMethod::Direct);  // 40 cells: far below 5000 free dofs
  CHECK(by_default == direct);
  const Eigen::VectorXd from_zero = solve(solvers::SolverMethod::Auto, 0, 1, &large);
  const bool cholmod = solvers::solverAvailable(solvers::SolverMethod::Cholmod);
  CHECK(large.linear_method ==
        (cholmod ? solvers::SolverMethod::Cholmod : solvers::SolverMethod::Direct));
  CHECK((from_zero - direct).lpNorm<Eigen::Infinity>() <= 1e-9 * direct.lpNorm<Eigen::Infinity>());
  CHECK(solve(solvers::SolverMethod::Auto, 0, 2, &large2) == from_zero);
  CHECK_THROWS_WITH(solve(solvers::SolverMethod::Auto, -1, 1, &large2),
                    Catch::Contains("auto_cholmod_unknowns"));
}
