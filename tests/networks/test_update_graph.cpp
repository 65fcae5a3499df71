// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// NetworkSystem::updateGraph: a system (and its integrator) kept across solve
// intervals while the tissue grows computes exactly what a new system on the
// grown graph computes (the right-hand side, the Jacobian, integration), and a
// graph of another structure is refused.
#include <catch2/catch.hpp>

#include <random>

#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_integrator.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"

using namespace tessella;
using namespace tessella::networks;

namespace {

// Reactions reading a cell property, the measure, a coordinate and a neighbourhood term; passive exchange;
// up-the-gradient PIN (the exponential weight) or with_the_flux PIN as a state.
NetworkModel model(bool dynamic_pin) {
  NetworkModel m;
  m.parameters = {{"p", 0.5}, {"d", 0.05}, {"KA", 10.0}};
  m.cell_properties = {"growth"};
  m.species.push_back({"auxin", "p * growth - d * auxin + 0.01 * x", 0.05});
  m.species.push_back({"A", "auxin^2 / (KA^2 + auxin^2) - 0.1 * A * measure + 0.01 * mean_auxin", 0.01});
  m.pin.species = "auxin";
  m.pin.base = 2.0;
  if (dynamic_pin) {
    m.pin.model = PinModel::WithTheFlux;
    m.pin.basal = 0.1;
    m.pin.production = 3.0;
    m.pin.decay = 0.5;
    m.pin.initial = 0.3;
  }
  return m;
}

// A hexagonal grid's graph with a growth property, and the same graph "grown": every cell's measure, each
// interface's measure and the property changed by different factors, the centroids moved.
NetworkGraph grid() {
  const Tissue tissue = hexagonalGrid(7, 6);
  GeometryCache geometry;
  NetworkGraph g = networkGraph(tissue, geometry, {});
  std::vector<double> growth(g.numCells());
  for (std::size_t c = 0; c < growth.size(); ++c) growth[c] = 1.0 + 0.1 * static_cast<double>(c % 5);
  g.properties["growth"] = growth;
  return g;
}

NetworkGraph grown(NetworkGraph g) {
  for (std::size_t c = 0; c < g.numCells(); ++c) {
    g.measure[c] *= 1.0 + 0.013 * static_cast<double>(c % 7);
    g.centroid[c] *= 1.05;
    g.properties["growth"][c] += 0.2;
  }
  for (std::size_t k = 0; k < g.interfaces.size(); ++k)
    g.interfaces[k].measure *= 1.0 + 0.02 * static_cast<double>(k % 3);
  return g;
}

std::vector<double> start(const NetworkSystem& s) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> noise(0.0, 0.5);
  std::vector<double> y(s.size());
  for (std::size_t c = 0; c < s.numCells(); ++c) {
    y[s.index(c, 0)] = (10.0 + noise(rng)) * s.graph().measure[c];
    y[s.index(c, 1)] = (1.0 + noise(rng)) * s.graph().measure[c];
  }
  for (std::size_t k = s.numSpecies() * s.numCells(); k < s.size(); ++k) y[k] = 0.3 + noise(rng);
  return y;
}

}  // namespace

TEST_CASE("A system updated with a grown graph computes what a new system on it computes, bit for bit",
          "[networks][update]") {
  for (const bool dynamic_pin : {false, true}) {
    for (const JacobianKind kind : {JacobianKind::Exact, JacobianKind::Neighbours}) {
      CAPTURE(dynamic_pin, jacobianKinds().name(kind));
      const NetworkGraph before = grid(), after = grown(grid());
      NetworkSystem kept(model(dynamic_pin), before, kind);
      const std::vector<double> y = start(kept);
      std::vector<double> ydot(kept.size()), fresh_ydot(kept.size());
      kept.rhs(0.0, y, ydot);  // used on the old graph first
      REQUIRE(kept.sameStructure(after));
      kept.updateGraph(after);
      NetworkSystem fresh(model(dynamic_pin), after, kind);
      kept.rhs(0.5, y, ydot);
      fresh.rhs(0.5, y, fresh_ydot);
      CHECK(ydot == fresh_ydot);
      CsrMatrix J, fresh_J;
      kept.jacobian(0.5, y, J);
      fresh.jacobian(0.5, y, fresh_J);
      CHECK(J.column == fresh_J.column);
      CHECK(J.value == fresh_J.value);
      // And the rates did change with the graph (the test would not notice a stale measure otherwise).
      NetworkSystem old(model(dynamic_pin), before, kind);
      std::vector<double> old_ydot(kept.size());
      old.rhs(0.5, y, old_ydot);
      CHECK(old_ydot != ydot);
    }
  }
}

TEST_CASE("An integrator kept across an updateGraph integrates as a new integrator on a new system",
          "[networks][update]") {
  for (const LinearSolver solver : {LinearSolver::Klu, LinearSolver::Gmres}) {
    CAPTURE(linearSolvers().name(solver));
    IntegratorOptions o;
    o.linear_solver = solver;
    const NetworkGraph before = grid(), after = grown(grid());
    // Kept: one system and integrator, two intervals, the graph grown between them.
    NetworkSystem kept(model(false), before, JacobianKind::Neighbours);
    std::vector<double> y = start(kept);
    std::vector<double> y_fresh = y;
    NetworkIntegrator integrator(kept, o);
    integrator.advance(y, 0.0, 2.0);
    kept.updateGraph(after);
    integrator.advance(y, 2.0, 4.0);
    // Fresh: a new system and integrator per interval.
    {
      NetworkSystem s(model(false), before, JacobianKind::Neighbours);
      NetworkIntegrator(s, o).advance(y_fresh, 0.0, 2.0);
    }
    {
      NetworkSystem s(model(false), after, JacobianKind::Neighbours);
      NetworkIntegrator(s, o).advance(y_fresh, 2.0, 4.0);
    }
    CHECK(y == y_fresh);
  }
}

TEST_CASE("updateGraph refuses a graph of another structure, naming what differs", "[networks][update]") {
  NetworkSystem system(model(false), grid());
  NetworkGraph swapped = grid();
  std::swap(swapped.interfaces[3], swapped.interfaces[4]);
  CHECK_FALSE(system.sameStructure(swapped));
  CHECK_THROWS_WITH(system.updateGraph(swapped), Catch::Contains("interface 3 joins cells"));
  NetworkGraph fewer = grid();
  fewer.interfaces.pop_back();
  CHECK_FALSE(system.sameStructure(fewer));
  CHECK_THROWS_AS(system.updateGraph(fewer), InputError);
  NetworkGraph no_property = grid();
  no_property.properties.clear();
  CHECK_FALSE(system.sameStructure(no_property));
  CHECK_THROWS_WITH(system.updateGraph(no_property), Catch::Contains("'growth'"));
}
