// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "jacobian_check.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_integrator.hpp"
#include "tessella/networks/reaction_set.hpp"

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

namespace {
// A ring of n cells of measures 1 + (c mod 7) / 10 at x = c, with a property `g`.
NetworkGraph ring(std::size_t n) {
  NetworkGraph g;
  for (std::size_t c = 0; c < n; ++c) {
    g.measure.push_back(1.0 + double(c % 7) / 10.0);
    g.centroid.push_back(Vec3(double(c), 0, 0));
    g.properties["g"].push_back(0.5 + double(c % 5) / 4.0);
  }
  for (std::size_t c = 0; c < n; ++c) {
    const int a = int(c), b = int((c + 1) % n);
    g.interfaces.push_back({std::min(a, b), std::max(a, b), 1.0 + double(c % 3) / 8.0, Vec3(1, 0, 0)});
  }
  return g;
}
}  // namespace

TEST_CASE("The reactions' part of the Jacobian is one cell's central differences, bit for bit, over blocks and threads",
          "[networks]") {
  // 4500 cells: several blocks of 128 cells, the last one short, and enough cells for the threads to share them.
  const std::size_t n = 4500, S = 3;
  NetworkModel m;
  m.species = {{"a", "p * g - d * a + a^2 * b / (1 + (a / K)^2) + 0.01 * x * c", 0.0},
               {"b", "a^3 - b * measure + mean_a", 0.0},
               {"c", "", 0.0}};
  m.parameters = {{"p", 1.0}, {"d", 0.5}, {"K", 0.7}};
  m.cell_properties = {"g"};
  const NetworkGraph graph = ring(n);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.2, 2.5);
  std::vector<double> y(n * S);
  for (double& v : y) v = u(rng);
  // Independently: each cell's values set one by one, the perturbed rate of one reaction at a time.
  ReactionSet one(m);
  const double root = std::cbrt(std::numeric_limits<double>::epsilon());
  std::vector<double> expected(n * S * S, 0.0);  // d rate_s / d c_q of cell c at c S S + s S + q
  for (std::size_t c = 0; c < n; ++c) {
    std::vector<double> conc(S);
    for (std::size_t q = 0; q < S; ++q) conc[q] = y[c * S + q] / graph.measure[c];
    // The neighbourhood: sum_a over the ring's two neighbours and mean_a.
    std::vector<double> nb(2 * S, 0.0);
    double walls = 0.0;
    for (const NetworkInterface& f : graph.interfaces)
      if (f.cell_i == int(c) || f.cell_j == int(c)) {
        const auto j = std::size_t(f.cell_i == int(c) ? f.cell_j : f.cell_i);
        for (std::size_t q = 0; q < S; ++q) nb[q] += f.measure * (y[j * S + q] / graph.measure[j]);
        walls += f.measure;
      }
    for (std::size_t q = 0; q < S; ++q) nb[S + q] = nb[q] / walls;
    const std::vector<double> props{graph.properties.at("g")[c]};
    one.set(0.25, graph.measure[c], graph.centroid[c], props, conc, nb);
    for (std::size_t q = 0; q < S; ++q) {
      const double h = root * std::max(std::abs(conc[q]), 1.0);
      for (std::size_t s = 0; s < S; ++s) {
        if (!one.reads(s, q)) continue;
        one.setConcentration(q, conc[q] + h);
        const double up = one.rate(s, c);
        one.setConcentration(q, conc[q] - h);
        const double down = one.rate(s, c);
        one.setConcentration(q, conc[q]);
        expected[(c * S + s) * S + q] = (up - down) / (2 * h);
      }
    }
  }
  for (std::size_t threads : {1, 2}) {
    NetworkSystem system(m, graph);
    system.setThreads(threads);
    CsrMatrix J;
    system.jacobian(0.25, y, J);
    std::size_t differ = 0;
    for (std::size_t c = 0; c < n; ++c)
      for (std::size_t s = 0; s < S; ++s)
        for (std::size_t q = 0; q < S; ++q) differ += J.at(c * S + s, c * S + q) != expected[(c * S + s) * S + q];
    INFO(threads << " threads");
    CHECK(differ == 0);
  }
}

TEST_CASE("A perturbed rate that is not finite names the lowest such cell, over blocks and threads", "[networks]") {
  // sqrt(a) at a = 0 is finite, at a - h it is not: the Jacobian fails at the first cell holding a = 0.
  const std::size_t n = 4500;
  NetworkModel m;
  m.species = {{"a", "-sqrt(a)", 0.0}};
  const NetworkGraph graph = ring(n);
  std::vector<double> y(n, 1.0);
  y[3000] = y[333] = y[4400] = 0.0;
  for (std::size_t threads : {1, 2}) {
    NetworkSystem system(m, graph);
    system.setThreads(threads);
    std::vector<double> ydot(n);
    system.rhs(0.0, y, ydot);
    CsrMatrix J;
    CHECK_THROWS_WITH(system.jacobian(0.0, y, J), Catch::Contains("in cell 333 "));
  }
}
