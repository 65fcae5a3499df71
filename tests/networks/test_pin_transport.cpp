// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>

#include "network_fixtures.hpp"
#include "tessella/networks/network_integrator.hpp"

using namespace tessella;
using namespace tessella::networks;

TEST_CASE("Up-the-gradient PIN allocation follows its formula", "[networks]") {
  // Three cells in a row; the middle one shares walls of measure 0.5 (left) and 2 (right).
  NetworkGraph g = testing::chainGraph({1.0, 2.0, 1.5}, {0.5, 2.0});
  NetworkModel m = testing::oneSpecies("auxin", 0.0);
  m.pin = {"auxin", PinModel::UpTheGradient, PinFunction::Exponential, 2.5, 1.0, 1.0, 1.7, 0.3};
  NetworkSystem system(m, g);
  const std::vector<double> c{0.4, 1.1, 2.0};
  std::vector<double> y{c[0] * 1.0, c[1] * 2.0, c[2] * 1.5};
  const auto sides = system.pin(y);
  auto f = [](double x) { return std::pow(2.5, x); };
  const double D1 = 0.3 + 0.5 * f(c[0]) + 2.0 * f(c[2]);
  CHECK(sides[0].ji == Approx(1.7 * 0.5 * f(c[0]) / D1));  // cell 1 toward cell 0
  CHECK(sides[1].ij == Approx(1.7 * 2.0 * f(c[2]) / D1));  // cell 1 toward cell 2
  CHECK(sides[0].ij == Approx(1.7 * 0.5 * f(c[1]) / (0.3 + 0.5 * f(c[1]))));  // cell 0: one neighbour
  // Polarity of the middle cell: PIN-weighted outward normals (+x toward 2, -x toward 0).
  const auto polarity = system.polarity(y);
  CHECK(polarity[1].x() == Approx(sides[1].ij - sides[0].ji));
  CHECK(polarity[1].y() == 0.0);
  // The rate: cell 0 receives T PIN_10 c_1 and sends T PIN_01 c_0.
  std::vector<double> ydot(3);
  system.rhs(0.0, y, ydot);
  CHECK(ydot[0] == Approx(1.0 * (sides[0].ji * c[1] - sides[0].ij * c[0])));
}

TEST_CASE("Smith et al.'s PIN allocation: PIN made with the species and a saturating efflux", "[networks]") {
  // The chain of the test above; P_i = P0 + P1 c_i, efflux T PIN_ij c_i^2 / (1 + s c_i^2).
  NetworkGraph g = testing::chainGraph({1.0, 2.0, 1.5}, {0.5, 2.0});
  NetworkModel m = testing::oneSpecies("auxin", 0.0);
  const double P0 = 0.6, P1 = 0.9, T = 1.4, s = 0.35, kappa = 0.3, b = 2.5;
  m.pin = {"auxin", PinModel::UpTheGradient, PinFunction::Exponential, b, 1.0, T, P0, kappa};
  m.pin.total_per_concentration = P1;
  m.pin.efflux = PinEfflux::Saturating;
  m.pin.efflux_saturation = s;
  NetworkSystem system(m, g);
  const std::vector<double> c{0.4, 1.1, 2.0}, V{1.0, 2.0, 1.5};
  std::vector<double> y{c[0] * V[0], c[1] * V[1], c[2] * V[2]};
  auto f = [&](double x) { return std::pow(b, x); };
  auto P = [&](double x) { return P0 + P1 * x; };
  auto efflux = [&](double x) { return x * x / (1 + s * x * x); };
  const double D0 = kappa + 0.5 * f(c[1]), D1 = kappa + 0.5 * f(c[0]) + 2.0 * f(c[2]), D2 = kappa + 2.0 * f(c[1]);
  const double pin01 = P(c[0]) * 0.5 * f(c[1]) / D0, pin10 = P(c[1]) * 0.5 * f(c[0]) / D1;
  const double pin12 = P(c[1]) * 2.0 * f(c[2]) / D1, pin21 = P(c[2]) * 2.0 * f(c[1]) / D2;
  const auto sides = system.pin(y);
  CHECK(sides[0].ij == Approx(pin01));
  CHECK(sides[0].ji == Approx(pin10));
  CHECK(sides[1].ij == Approx(pin12));
  CHECK(sides[1].ji == Approx(pin21));
  std::vector<double> ydot(3);
  system.rhs(0.0, y, ydot);
  const double J01 = T * pin01 * efflux(c[0]), J10 = T * pin10 * efflux(c[1]);
  const double J12 = T * pin12 * efflux(c[1]), J21 = T * pin21 * efflux(c[2]);
  CHECK(ydot[0] == Approx(J10 - J01).epsilon(1e-12));
  CHECK(ydot[1] == Approx(J01 + J21 - J10 - J12).epsilon(1e-12));
  CHECK(ydot[2] == Approx(J12 - J21).epsilon(1e-12));
  // Saturation: the efflux per unit PIN of a cell tends to T / s, whatever its concentration.
  CHECK(m.pin.effluxFactor(1e4) / m.pin.cellPin(1e4) == Approx(T / s).epsilon(1e-7));
}

TEST_CASE("Two cells with PIN only and no saturation exchange like passive transport", "[networks]") {
  // Each cell has one neighbour, so PIN_ij = P: the fluxes are T P c_i each way.
  const double V1 = 1.0, V2 = 3.0, T = 0.8, P = 1.2;
  NetworkModel m = testing::oneSpecies("a", 0.0);
  m.pin.species = "a";
  m.pin.rate = T;
  m.pin.total = P;
  m.pin.function = PinFunction::Power;
  m.pin.exponent = 2.0;
  NetworkSystem system(m, testing::chainGraph({V1, V2}, {0.7}));
  const double c1 = 2.0, c2 = 0.5, M = V1 * c1 + V2 * c2;
  std::vector<double> y{V1 * c1, V2 * c2};
  IntegratorOptions o;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-14;
  NetworkIntegrator integrator(system, o);
  const double t1 = 1.3;
  integrator.advance(y, 0.0, t1);
  const double lambda = T * P * (1 / V1 + 1 / V2);
  const double delta = (c1 - c2) * std::exp(-lambda * t1);
  const double e1 = (M + V2 * delta) / (V1 + V2);
  CHECK(y[0] / V1 == Approx(e1).epsilon(1e-8));
  CHECK(y[1] / V2 == Approx(e1 - delta).epsilon(1e-8));
}
