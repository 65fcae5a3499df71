// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// PIN as a state per interface side: with_the_flux (canalization) and a user
// expression. Closed-form steady state of two cells, exact conservation of
// the transported amount, the Jacobian against central differences, and the
// expression model against with_the_flux written as an expression.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "jacobian_check.hpp"
#include "network_fixtures.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_integrator.hpp"

using namespace tessella;
using namespace tessella::networks;

namespace {

PinTransport flux(bool bounded) {
  PinTransport p;
  p.species = "auxin";
  p.model = PinModel::WithTheFlux;
  p.rate = 2.0;
  p.basal = 0.1;
  p.production = 3.0;
  p.decay = 0.5;
  p.flux_exponent = 2.0;
  p.flux_saturation = 0.2;
  p.bounded = bounded;
  p.total = 2.0;
  p.initial = 0.3;
  return p;
}

// The same rate as flux(bounded) as a muparser expression.
std::string fluxExpression(bool bounded) {
  const std::string h = "(flux > 0 ? flux^2 : 0)";
  return "(0.1 + 3 * " + h + " / (1 + 0.2 * " + h + "))" + (bounded ? " * (1 - pin_cell / 2)" : "") +
         " - 0.5 * pin";
}

std::vector<double> randomState(const NetworkSystem& s, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.2, 2.0);
  std::vector<double> y(s.size());
  for (double& v : y) v = u(rng);
  return y;
}

}  // namespace

TEST_CASE("Dynamic PIN: the state holds two densities per interface after the amounts", "[networks][pin]") {
  NetworkGraph g = testing::chainGraph({1.0, 2.0, 1.5}, {0.5, 2.0});
  NetworkModel m = testing::oneSpecies("auxin", 0.1);
  m.pin = flux(false);
  NetworkSystem system(m, g);
  CHECK(system.numPinStates() == 4);
  CHECK(system.size() == 3 + 4);
  CHECK(system.pinIndex(1, 1) == 6);
  const std::vector<double> y{1, 2, 0.75, 0.5, 0.25, 1.5, 0.75};
  const auto amount = system.pin(y), density = system.pinDensity(y);
  CHECK(density[1].ij == 1.5);
  CHECK(density[1].ji == 0.75);
  CHECK(amount[0].ij == 0.5 * 0.5);
  CHECK(amount[1].ji == 2.0 * 0.75);
  // The efflux T L p_ij c_i: the rate of the amounts, checked by hand.
  std::vector<double> ydot(system.size());
  system.rhs(0.0, y, ydot);
  const double c0 = 1.0, c1 = 1.0, c2 = 0.5;
  const double J01 = 2.0 * 0.5 * (0.5 * c0 - 0.25 * c1) + 0.1 * 0.5 * (c0 - c1);
  const double J12 = 2.0 * 2.0 * (1.5 * c1 - 0.75 * c2) + 0.1 * 2.0 * (c1 - c2);
  CHECK(ydot[0] == Approx(-J01));
  CHECK(ydot[1] == Approx(J01 - J12));
  CHECK(ydot[2] == Approx(J12));
  // The density's rate: (basal + rho h(phi)) - mu p with phi the net flux density.
  const double phi12 = J12 / 2.0;
  REQUIRE(phi12 > 0);
  const double h = phi12 * phi12 / (1 + 0.2 * phi12 * phi12);
  CHECK(ydot[system.pinIndex(1, 0)] == Approx(0.1 + 3 * h - 0.5 * 1.5));
  CHECK(ydot[system.pinIndex(1, 1)] == Approx(0.1 - 0.5 * 0.75));  // phi21 < 0: no flux-driven production
  // Polarity: sum of L p n over the interfaces, normals (1, 0, 0) from i to j.
  const auto pol = system.polarity(y);
  CHECK(pol[1].x() == Approx(2.0 * 1.5 - 0.5 * 0.25));
}

TEST_CASE("Dynamic PIN: the Jacobian matches central differences", "[networks][pin]") {
  Tissue t = hexagonalGrid(5, 4, 1.0);
  GeometryCache geometry;
  NetworkModel m;
  m.species = {{"auxin", "p - d * auxin + auxin * b / (1 + auxin^2)", 0.3}, {"b", "auxin^2 - b", 0.1}};
  m.parameters = {{"p", 1.0}, {"d", 0.5}};
  const bool bounded = GENERATE(false, true);
  const bool expression = GENERATE(false, true);
  m.pin = flux(bounded);
  if (expression) {
    m.pin.model = PinModel::Expression;
    m.pin.expression = fluxExpression(bounded) + " + 0.05 * c_i * c_j / (1 + pin_opposite) + 0.01 * wall * measure";
  }
  INFO("bounded " << bounded << ", expression " << expression);
  NetworkSystem system(m, networkGraph(t, geometry, {}));
  testing::compareWithDifferences(system, randomState(system, 7));
}

TEST_CASE("The expression model reproduces with_the_flux written as an expression", "[networks][pin]") {
  Tissue t = hexagonalGrid(4, 4, 1.0);
  GeometryCache geometry;
  const NetworkGraph graph = networkGraph(t, geometry, {});
  const bool bounded = GENERATE(false, true);
  NetworkModel a = testing::oneSpecies("auxin", 0.2, "1 - 0.3 * auxin");
  a.pin = flux(bounded);
  NetworkModel b = a;
  b.pin.model = PinModel::Expression;
  b.pin.expression = fluxExpression(bounded);
  NetworkSystem sa(a, graph), sb(b, graph);
  const std::vector<double> y = randomState(sa, 11);
  std::vector<double> fa(sa.size()), fb(sb.size());
  sa.rhs(0.0, y, fa);
  sb.rhs(0.0, y, fb);
  for (std::size_t k = 0; k < fa.size(); ++k) CHECK(fb[k] == Approx(fa[k]).epsilon(1e-13).margin(1e-14));
}

TEST_CASE("with_the_flux: two cells, a source and a sink, reach the closed-form steady state", "[networks][pin]") {
  // Cell 0 makes auxin at p per unit measure, cell 1 degrades it at rate d: at the steady state the net
  // flux from 0 into 1 carries all that is made, phi = p V0 / L per unit wall measure, and
  //   c1 = p V0 / (d V1),
  //   p_10 = basal / (mu [+ basal L / P]),            (phi_10 = -phi < 0: basal production only)
  //   p_01 = a / (mu [+ a L / P]),  a = basal + rho h(phi),
  //   c0 = (phi + (T p_10 + D) c1) / (T p_01 + D)     (phi = T (p_01 c0 - p_10 c1) + D (c0 - c1));
  // the bracketed terms with a bounded cell PIN (B = 1 - L p / P, each cell has one interface).
  const double V0 = 1.0, V1 = 1.5, L = 0.8, p = 1.0, d = 0.5, D = 0.1;
  NetworkGraph g = testing::chainGraph({V0, V1}, {L});
  g.properties["source"] = {1.0, 0.0};
  NetworkModel m = testing::oneSpecies("auxin", D, "p * source - d * (1 - source) * auxin");
  m.parameters = {{"p", p}, {"d", d}};
  m.cell_properties = {"source"};
  const bool bounded = GENERATE(false, true);
  m.pin = flux(bounded);
  const PinTransport& q = m.pin;
  NetworkSystem system(m, g);
  std::vector<double> y{0.5 * V0, 0.5 * V1, q.initial, q.initial};
  IntegratorOptions o;
  o.relative_tolerance = 1e-11;
  o.absolute_tolerance = 1e-13;
  NetworkIntegrator(system, o).advance(y, 0.0, 400.0);
  const double phi = p * V0 / L;
  const double a = q.basal + q.production * phi * phi / (1 + q.flux_saturation * phi * phi);
  const double p10 = q.basal / (q.decay + (bounded ? q.basal * L / q.total : 0.0));
  const double p01 = a / (q.decay + (bounded ? a * L / q.total : 0.0));
  const double c1 = p * V0 / (d * V1);
  const double c0 = (phi + (q.rate * p10 + D) * c1) / (q.rate * p01 + D);
  INFO("bounded " << bounded);
  CHECK(y[0] / V0 == Approx(c0).epsilon(1e-8));
  CHECK(y[1] / V1 == Approx(c1).epsilon(1e-8));
  CHECK(y[system.pinIndex(0, 0)] == Approx(p01).epsilon(1e-8));
  CHECK(y[system.pinIndex(0, 1)] == Approx(p10).epsilon(1e-8));
  if (bounded) CHECK(L * p01 < q.total);
}

TEST_CASE("with_the_flux transport conserves the total amount to 1e-12 (KLU and GMRES)", "[networks][pin]") {
  Tissue t = hexagonalGrid(8, 7, 1.0);
  GeometryCache geometry;
  NetworkModel m = testing::oneSpecies("auxin", 0.05);
  m.pin = flux(GENERATE(false, true));
  const LinearSolver solver = GENERATE(LinearSolver::Klu, LinearSolver::Gmres);
  NetworkSystem system(m, networkGraph(t, geometry, {}));
  std::vector<double> y = randomState(system, 3);
  const double before = system.totalAmount(y, 0);
  IntegratorOptions o;
  o.linear_solver = solver;
  NetworkIntegrator(system, o).advance(y, 0.0, 20.0);
  CHECK(std::abs(system.totalAmount(y, 0) - before) <= 1e-12 * before);
  // Something happened: the PIN densities left their start.
  const std::vector<double> start = randomState(system, 3);
  double moved = 0.0;
  for (std::size_t k = system.numCells(); k < y.size(); ++k) moved = std::max(moved, std::abs(y[k] - start[k]));
  CHECK(moved > 0.1);
}

TEST_CASE("Dynamic PIN models are validated", "[networks][pin]") {
  NetworkModel m = testing::oneSpecies("auxin", 0.0);
  m.pin = flux(true);
  m.pin.total = 0.0;
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("bounded PIN needs total > 0"));
  m.pin = flux(false);
  m.pin.flux_exponent = 0.5;
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("flux_exponent 0.5"));
  m.pin = flux(false);
  m.pin.model = PinModel::Expression;
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("needs pin.expression"));
  m.pin.expression = "1 - pin";
  m.parameters = {{"flux", 1.0}};
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("parameter 'flux' is a variable of the PIN expression"));
  m.parameters.clear();
  m.pin.expression = "1 - pin * unknown";
  CHECK_THROWS_WITH(NetworkSystem(m, testing::chainGraph({1, 1}, {1})), Catch::Contains("unknown"));
  m.pin.expression = "pin / (c_i - c_i)";
  NetworkSystem s(m, testing::chainGraph({1, 1}, {1}));
  std::vector<double> y{1, 1, 1, 1}, ydot(4);
  CHECK_THROWS_WITH(s.rhs(0.0, y, ydot), Catch::Contains("gave") && Catch::Contains("cell 0's side"));
}

TEST_CASE("A CVODE failure in a PIN density names the side and the interface", "[networks][pin][errors]") {
  // dp/dt = 1000 p^2 blows up at t = 1e-3 / p0; the amounts do not move (no transport, no reaction).
  NetworkModel m = testing::oneSpecies("auxin", 0.0);
  m.pin = flux(false);
  m.pin.rate = 0.0;
  m.pin.model = PinModel::Expression;
  m.pin.expression = "1000 * pin^2";
  NetworkSystem system(m, testing::chainGraph({1, 1, 1}, {1, 1}));
  std::vector<double> y{1, 1, 1, 0.5, 1.0, 0.5, 0.5};  // cell 1's side of interface 0 is the largest
  IntegratorOptions o;
  o.max_steps = 20;
  try {
    NetworkIntegrator(system, o).advance(y, 0.0, 1.0);
    FAIL("no error");
  } catch (const NetworkIntegrationError& e) {
    CHECK_THAT(e.what(), Catch::Contains("the PIN of 'auxin' on cell 1's side of its interface with cell 0"));
    CHECK(e.cell() == 1);
    CHECK(e.species() == "auxin");
  }
}
