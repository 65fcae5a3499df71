// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "network_fixtures.hpp"
#include "tessella/networks/network_integrator.hpp"

using namespace tessella;
using namespace tessella::networks;

TEST_CASE("Logistic growth in every cell follows its closed form", "[networks]") {
  NetworkModel m = testing::oneSpecies("a", 0.0, "r * a * (1 - a / K)");
  m.parameters = {{"r", 1.3}, {"K", 4.0}};
  const std::vector<double> V{1.0, 2.5, 0.4};
  NetworkSystem system(m, testing::chainGraph(V, {1.0, 1.0}));
  const std::vector<double> c0{0.1, 1.0, 6.0};
  std::vector<double> y(3);
  for (std::size_t i = 0; i < 3; ++i) y[i] = V[i] * c0[i];
  IntegratorOptions o;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-14;
  NetworkIntegrator integrator(system, o);
  const double T = 3.0;
  integrator.advance(y, 0.0, T);
  for (std::size_t i = 0; i < 3; ++i) {
    const double e = std::exp(1.3 * T);
    const double exact = 4.0 * c0[i] * e / (4.0 + c0[i] * (e - 1.0));
    CHECK(y[i] / V[i] == Approx(exact).epsilon(1e-7));
  }
}

TEST_CASE("Hill production, decay and exchange match a fine Runge-Kutta reference", "[networks]") {
  // Two species in two cells: a activates itself (Hill, n = 2) and b; a is exchanged.
  NetworkModel m;
  m.species = {{"a", "v * a^2 / (K^2 + a^2) + p - d * a - a * b", 0.4}, {"b", "a - 0.5 * b", 0.0}};
  m.parameters = {{"v", 3.0}, {"K", 1.0}, {"p", 0.1}, {"d", 1.0}};
  const double V1 = 1.0, V2 = 2.0, L = 0.8, P = 0.4;
  NetworkSystem system(m, testing::chainGraph({V1, V2}, {L}));
  using State = std::array<double, 4>;  // concentrations a1, b1, a2, b2
  auto f = [&](const State& c) {
    auto ra = [](double a, double b) { return 3.0 * a * a / (1.0 + a * a) + 0.1 - a - a * b; };
    const double J = P * L * (c[0] - c[2]);  // amount per time from 1 to 2
    return State{ra(c[0], c[1]) - J / V1, c[0] - 0.5 * c[1], ra(c[2], c[3]) + J / V2, c[2] - 0.5 * c[3]};
  };
  State c{2.0, 0.0, 0.2, 0.1};
  std::vector<double> y{V1 * c[0], V1 * c[1], V2 * c[2], V2 * c[3]};
  const double T = 5.0, h = 1e-4;
  for (int k = 0; k < static_cast<int>(T / h + 0.5); ++k) {
    auto add = [](const State& a, const State& b, double s) {
      State r;
      for (std::size_t i = 0; i < 4; ++i) r[i] = a[i] + s * b[i];
      return r;
    };
    const State k1 = f(c), k2 = f(add(c, k1, h / 2)), k3 = f(add(c, k2, h / 2)), k4 = f(add(c, k3, h));
    for (std::size_t i = 0; i < 4; ++i) c[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  IntegratorOptions o;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-13;
  NetworkIntegrator integrator(system, o);
  integrator.advance(y, 0.0, T);
  CHECK(y[0] / V1 == Approx(c[0]).epsilon(1e-7));
  CHECK(y[1] / V1 == Approx(c[1]).epsilon(1e-7));
  CHECK(y[2] / V2 == Approx(c[2]).epsilon(1e-7));
  CHECK(y[3] / V2 == Approx(c[3]).epsilon(1e-7));
}

TEST_CASE("Reactions read the measure, the centroid, time and cell properties", "[networks]") {
  NetworkModel m = testing::oneSpecies("a", 0.0, "measure + 10 * x + 100 * q + 1000 * t");
  m.cell_properties = {"q"};
  NetworkGraph g = testing::chainGraph({1.5, 2.5}, {1.0});
  g.properties["q"] = {0.25, 0.5};
  NetworkSystem system(m, g);
  std::vector<double> y{1.0, 1.0}, ydot(2);
  system.rhs(0.002, y, ydot);
  CHECK(ydot[0] == Approx(1.5 * (1.5 + 0.0 + 25.0 + 2.0)));
  CHECK(ydot[1] == Approx(2.5 * (2.5 + 10.0 + 50.0 + 2.0)));
}
