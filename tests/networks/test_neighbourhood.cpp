// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Neighbourhood terms in reactions: sum_<s> (sum over the neighbours j of
// L_ij c_j) and mean_<s> (divided by sum_j L_ij). Their values by hand on a
// chain, a ring's cosine modes in closed form, the Jacobian against central
// differences, and name clashes.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "jacobian_check.hpp"
#include "network_fixtures.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_integrator.hpp"

using namespace tessella;
using namespace tessella::networks;

TEST_CASE("sum_ and mean_ are the interface-weighted sum and mean of the neighbours", "[networks][neighbourhood]") {
  // Cells 0 - 1 - 2 with walls 0.5 and 2; the middle cell's rate reads both terms.
  NetworkGraph g = testing::chainGraph({1.0, 2.0, 1.5}, {0.5, 2.0});
  NetworkModel m = testing::oneSpecies("a", 0.0, "sum_a + 10 * mean_a");
  NetworkSystem system(m, g);
  const std::vector<double> c{0.4, 1.1, 2.0};
  const std::vector<double> y{c[0] * 1.0, c[1] * 2.0, c[2] * 1.5};
  std::vector<double> ydot(3);
  system.rhs(0.0, y, ydot);
  const double sum1 = 0.5 * c[0] + 2.0 * c[2], mean1 = sum1 / 2.5;
  CHECK(ydot[1] == Approx(2.0 * (sum1 + 10 * mean1)));   // amounts: measure times the rate
  CHECK(ydot[0] == Approx(1.0 * (0.5 * c[1] + 10 * c[1])));  // one neighbour: the mean is its value
}

TEST_CASE("A reaction toward the neighbours' mean on a ring decays its cosine modes in closed form",
          "[networks][neighbourhood]") {
  // dc_i/dt = k (mean_j c_j - c_i) on a ring of N equal cells and walls: a discrete Laplacian, so
  // c_i = 2 + exp(-k (1 - cos theta) t) cos(theta i) with theta = 2 pi m / N. The second species does the
  // same with sum_b (walls of measure 1, two neighbours: sum = 2 mean).
  const std::size_t N = 12, mode = 2;
  const double k = 0.7, theta = 2 * std::numbers::pi * mode / N, T = 3.0;
  NetworkGraph g;
  g.measure.assign(N, 1.0);
  for (std::size_t i = 0; i < N; ++i) g.centroid.push_back(Vec3(double(i), 0, 0));
  for (std::size_t i = 0; i < N; ++i) {
    const int a = int(i), b = int((i + 1) % N);
    g.interfaces.push_back({std::min(a, b), std::max(a, b), 1.0, Vec3(1, 0, 0)});
  }
  NetworkModel m;
  m.species = {{"a", "k * (mean_a - a)", 0.0}, {"b", "k * (sum_b / 2 - b)", 0.0}};
  m.parameters = {{"k", k}};
  NetworkSystem system(m, g);
  std::vector<double> y(2 * N);
  for (std::size_t i = 0; i < N; ++i) y[2 * i] = y[2 * i + 1] = 2 + std::cos(theta * double(i));
  IntegratorOptions o;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-12;
  NetworkIntegrator(system, o).advance(y, 0.0, T);
  const double decay = std::exp(-k * (1 - std::cos(theta)) * T);
  for (std::size_t i = 0; i < N; ++i) {
    const double exact = 2 + decay * std::cos(theta * double(i));
    CHECK(y[2 * i] == Approx(exact).epsilon(1e-7));
    CHECK(y[2 * i + 1] == Approx(exact).epsilon(1e-7));
  }
}

TEST_CASE("The Jacobian with neighbourhood terms matches central differences", "[networks][neighbourhood]") {
  Tissue t = hexagonalGrid(5, 4, 1.0);
  GeometryCache geometry;
  NetworkModel m;
  m.species = {{"a", "p - d * a + sum_b * a / (1 + mean_a^2)", 0.3}, {"b", "a^2 - b + 0.1 * mean_b", 0.0}};
  m.parameters = {{"p", 1.0}, {"d", 0.5}};
  m.pin.species = "a";
  m.pin.rate = 1.5;
  SECTION("up_the_gradient") {}
  SECTION("with_the_flux") {
    m.pin.model = PinModel::WithTheFlux;
    m.pin.bounded = true;
    m.pin.total = 4.0;
  }
  NetworkSystem system(m, networkGraph(t, geometry, {}));
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.2, 2.0);
  std::vector<double> y(system.size());
  for (double& v : y) v = u(rng);
  testing::compareWithDifferences(system, y);
}

TEST_CASE("Neighbourhood names cannot be species or parameters", "[networks][neighbourhood][errors]") {
  NetworkModel m;
  m.species = {{"a", "", 0.0}, {"sum_a", "", 0.0}};
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("'sum_a' names both a species and the neighbourhood term"));
  m.species = {{"a", "mean_c", 0.0}};
  CHECK_THROWS_WITH(NetworkSystem(m, testing::chainGraph({1, 1}, {1})), Catch::Contains("mean_c"));
}
