// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "jacobian_check.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_integrator.hpp"

using namespace tessella;
using namespace tessella::networks;

using testing::compareWithDifferences;

TEST_CASE("The Jacobian matches central differences: reactions, passive transport, PIN", "[networks]") {
  Tissue t = hexagonalGrid(5, 4, 1.0);
  GeometryCache geometry;
  NetworkModel m;
  m.species = {{"a", "p - d * a + a * b / (1 + a^2)", 0.3}, {"b", "a^2 - b", 0.1}};
  m.parameters = {{"p", 1.0}, {"d", 0.5}};
  m.pin.species = "a";
  m.pin.rate = 1.5;
  m.pin.saturation = 0.2;
  SECTION("exponential") { m.pin.function = PinFunction::Exponential; }
  SECTION("power") {
    m.pin.function = PinFunction::Power;
    m.pin.exponent = 2.0;
  }
  SECTION("Smith et al.: saturating efflux, PIN made with the species") {
    m.pin.efflux = PinEfflux::Saturating;
    m.pin.efflux_saturation = 0.4;
    m.pin.total_per_concentration = 0.7;
  }
  SECTION("linear efflux, PIN made with the species, power weight") {
    m.pin.function = PinFunction::Power;
    m.pin.exponent = 2.0;
    m.pin.total_per_concentration = 1.3;
  }
  NetworkSystem system(m, networkGraph(t, geometry, {}));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.2, 2.0);
  std::vector<double> y(system.size());
  for (double& v : y) v = u(rng);
  compareWithDifferences(system, y);
}

TEST_CASE("The neighbours Jacobian is sparser, keeps zero column sums and integrates to the same result",
          "[networks]") {
  Tissue t = hexagonalGrid(6, 5, 1.0);
  GeometryCache geometry;
  NetworkModel m;
  m.species = {{"a", "", 0.3}};
  m.pin.species = "a";
  m.pin.rate = 1.5;
  m.pin.base = 2.0;
  const NetworkGraph graph = networkGraph(t, geometry, {});
  NetworkSystem exact(m, graph, JacobianKind::Exact), near(m, graph, JacobianKind::Neighbours);
  CHECK(near.pattern().column.size() < exact.pattern().column.size());
  // Every row of the neighbours pattern: the cell and its neighbours only.
  for (std::size_t c = 0; c < graph.numCells(); ++c) {
    std::size_t neighbours = 0;
    for (const NetworkInterface& f : graph.interfaces) neighbours += (f.cell_i == int(c) || f.cell_j == int(c));
    CHECK(near.pattern().row_start[c + 1] - near.pattern().row_start[c] == neighbours + 1);
  }
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.5, 3.0);
  std::vector<double> y(exact.size());
  for (double& v : y) v = u(rng);
  for (NetworkSystem* s : {&exact, &near}) {
    CsrMatrix J;
    s->jacobian(0.0, y, J);
    std::vector<double> column_sum(s->size(), 0.0);
    double largest = 0.0;
    for (std::size_t k = 0; k < J.column.size(); ++k) {
      column_sum[J.column[k]] += J.value[k];
      largest = std::max(largest, std::abs(J.value[k]));
    }
    for (double v : column_sum) CHECK(std::abs(v) <= 1e-14 * largest * 20);
  }
  IntegratorOptions o;
  o.relative_tolerance = 1e-9;
  o.absolute_tolerance = 1e-12;
  std::vector<double> ye = y, yn = y;
  NetworkIntegrator(exact, o).advance(ye, 0.0, 5.0);
  NetworkIntegrator(near, o).advance(yn, 0.0, 5.0);
  const double total = exact.totalAmount(y, 0);
  CHECK(std::abs(near.totalAmount(yn, 0) - total) <= 1e-12 * total);
  for (std::size_t k = 0; k < y.size(); ++k) CHECK(yn[k] == Approx(ye[k]).epsilon(1e-6));
}
