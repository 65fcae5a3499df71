// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Lockhart-Ortega growth of rest lengths: the pressurised ring against the
// closed-form solution of its growth ODE, and rest lengths through divisions.
#include <catch2/catch.hpp>

#include "ring.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/mechanics/turgor_growth_step.hpp"
#include "tessella/mechanics/wall_state.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

#include <cmath>
#include <numbers>

using namespace tessella;
using namespace tessella::mechanics;

namespace {

// The ring's growth ODE dL0/dt = phi L0 max(eps - eps_y, 0) with the
// equilibrium strain eps = c L0 / (1 - c L0), c = P / (2 S tan(pi/N)), i.e.
// dL0/dt = phi L0 (alpha L0 - eps_y) / (1 - c L0), alpha = c (1 + eps_y).
// Separating variables (partial fractions) gives the primitive
//   G(L) = -ln(L) / eps_y + ln(alpha L - eps_y) / (eps_y (1 + eps_y)),
// so G(L0(t)) = G(L0(0)) + phi t; G increases on (eps_y / alpha, 1 / c).
double primitive(double L, double c, double eps_y) {
  const double alpha = c * (1 + eps_y);
  return -std::log(L) / eps_y + std::log(alpha * L - eps_y) / (eps_y * (1 + eps_y));
}

double closedFormRestLength(double L_start, double t, double phi, double c, double eps_y) {
  const double target = primitive(L_start, c, eps_y) + phi * t;
  double lo = L_start, hi = 1.0 / c;  // bisection: G is increasing there
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (primitive(mid, c, eps_y) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct RingRun {
  double rest_length;   // L0 at the end
  double worst_strain;  // largest |solved strain - closed form| over the steps
};

RingRun growRing(int n, double L0, double S, double P, double phi, double eps_y, double T, int steps) {
  Tissue ring = test::ringTissue(n, L0);
  TurgorGrowthParams params;
  params.youngs_modulus = S;
  params.thickness = 1.0;
  params.pressure = P;
  params.growth = {phi, eps_y};
  params.supports.pin = true;
  params.supports.pin_point = ring.position(VertexId(0));
  params.solver.relative_tolerance = 1e-13;
  const double dt = T / steps;
  RingRun run{0.0, 0.0};
  const WallId wall(0);
  for (int k = 0; k < steps; ++k) {
    const double rest_before = ring.wallProperties().has(kRestLengthName)
                                   ? ring.wallProperties().get<double>(kRestLengthName)[wall]
                                   : L0;
    turgorGrowthStep(ring, params, dt);
    const double a = test::ringLoad(n, P, S, rest_before);
    const double strain = ring.wallProperties().get<double>(kWallStrainName)[wall];
    run.worst_strain = std::max(run.worst_strain, std::abs(strain - a / (1 - a)));
  }
  run.rest_length = ring.wallProperties().get<double>(kRestLengthName)[wall];
  return run;
}

}  // namespace

TEST_CASE("strain growth: the law's rate and its exact step at constant strain", "[mechanics]") {
  const StrainGrowthLaw law{2.0, 0.1};
  CHECK(law.relativeRate(0.05) == 0.0);
  CHECK(law.relativeRate(0.3) == Approx(0.4));
  CHECK(law.grownRestLength(1.5, 0.3, 0.25) == Approx(1.5 * std::exp(0.1)));
  CHECK(law.grownRestLength(1.5, 0.0, 10.0) == 1.5);
  CHECK_THROWS_WITH((StrainGrowthLaw{-1.0, 0.0}.check()), Catch::Contains("extensibility -1"));
  CHECK_THROWS_WITH((StrainGrowthLaw{1.0, -0.5}.check()), Catch::Contains("threshold -0.5"));
}

TEST_CASE("strain growth: a pressurised ring's rest length follows the closed form of its growth ODE",
          "[mechanics]") {
  const int n = 6;
  const double L0 = 1.0, S = 1.0, phi = 1.0, eps_y = 0.1, T = 1.0;
  const double P = 0.2 * 2 * S * std::tan(std::numbers::pi / n) / L0;  // a = 0.2 at the start: strain 0.25
  const double c = P / (2 * S * std::tan(std::numbers::pi / n));
  const double exact = closedFormRestLength(L0, T, phi, c, eps_y);
  REQUIRE(exact > 1.1 * L0);       // the ring grows noticeably
  REQUIRE(c * exact < 0.5);        // and stays far from its limit load
  const RingRun coarse = growRing(n, L0, S, P, phi, eps_y, T, 40);
  const RingRun fine = growRing(n, L0, S, P, phi, eps_y, T, 80);
  // Every step's equilibrium strain is the closed form's.
  CHECK(coarse.worst_strain < 1e-10);
  CHECK(fine.worst_strain < 1e-10);
  // The step (strain held over dt) is first order: the error halves with dt.
  const double e_coarse = std::abs(coarse.rest_length - exact), e_fine = std::abs(fine.rest_length - exact);
  CAPTURE(exact, coarse.rest_length, fine.rest_length, e_coarse, e_fine);
  CHECK(e_fine < 5e-3 * exact);
  CHECK(e_coarse / e_fine == Approx(2.0).epsilon(0.1));
}

TEST_CASE("strain growth: below the threshold nothing grows", "[mechanics]") {
  const int n = 5;
  const double S = 1.0;
  const double P = 0.05 * 2 * S * std::tan(std::numbers::pi / n);  // strain 0.05 / 0.95 < 0.1
  const RingRun run = growRing(n, 1.0, S, P, 3.0, 0.1, 1.0, 5);
  CHECK(run.rest_length == Approx(1.0).epsilon(1e-14));  // the ring built with side 1 (to round-off)
}

TEST_CASE("strain growth: divided walls carry their rest length by length, new walls start at rest",
          "[mechanics]") {
  Tissue tissue = rectangularGrid(2, 1, 1.0, 1.0);
  PropertyColumn<double>& rest = restLengths(tissue);
  for (WallId w : tissue.walls()) rest[w] = 0.8 * wallMeasure(tissue, w);
  const std::size_t slots_before = tissue.slots(1);
  std::vector<double> rest_before(rest.values().begin(), rest.values().end());
  // Cut the left cell off-centre by a vertical plane at x = 0.3.
  const CellSplit split = tissue.splitCell(CellId(0), Plane{Vec3(0.3, 0.5, 0), Vec3(1, 0, 0)});
  const PropertyColumn<double>& after = tissue.wallProperties().get<double>(kRestLengthName);
  CHECK(after[split.wall] == 0.0);  // the new wall: unset until the next mechanics step
  for (WallId w : tissue.walls()) {
    if (w == split.wall) continue;
    // Old walls and the parts of split ones: 0.8 of their current length,
    // so a split wall's rest length went to its parts in proportion to their lengths.
    CAPTURE(w.index(), slots_before);
    CHECK(after[w] == Approx(0.8 * wallMeasure(tissue, w)).epsilon(1e-12));
  }
  // The parts of every split wall add up to the mother's rest length.
  double total_after = 0.0, total_before = 0.0;
  for (WallId w : tissue.walls())
    if (w != split.wall) total_after += after[w];
  for (double r : rest_before) total_before += r;
  CHECK(total_after == Approx(total_before).epsilon(1e-12));
  CHECK(initialiseRestLengths(tissue) == 1);
  CHECK(after[split.wall] == Approx(wallMeasure(tissue, split.wall)).epsilon(1e-14));
  // And a mechanics step runs on the divided tissue.
  TurgorGrowthParams params;
  params.pressure = 0.05;
  params.supports.pin = true;
  turgorGrowthStep(tissue, params, 0.1);
  CHECK(validate(tissue).ok);
}
