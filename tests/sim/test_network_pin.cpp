// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Dynamic PIN (network.pin.model: with_the_flux, expression) in the loop: the
// densities as wall properties through growth and divisions (amounts
// conserved), a restart from a snapshot that ends as the uninterrupted run,
// and errors at their keys.

#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "tessella/io/wall_vtu.hpp"
#include "tessella/networks/network_graph.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/network_stage.hpp"
#include "tessella/tissue/geometry.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using tessella::sim::test::ScratchDir;

namespace {

// Transport only (no reactions): auxin moves, PIN grows with the flux; the tissue grows and divides.
const std::string kFluxConfig = R"(
rng_seed: 4
tissue: {generator: rectangular_grid, rectangular_grid: {nx: 6, ny: 3}}
growth: {field: anisotropic, anisotropic: {rates: [0.1, 0.05, 0]}}
division: {rule: main_axis, size: 1.3}
network:
  mode: transient
  species:
    auxin: {initial: "1 + 0.5 * x", noise: 0.2, permeability: 0.05}
  pin:
    species: auxin
    model: with_the_flux
    rate: 1
    initial: 0.2
    basal: 0.05
    production: 30
    decay: 0.3
    bounded: true
    total: 3
)";

double sumProperty(const Tissue& t, const std::string& name) {
  const auto& column = t.cellProperties().get<double>(name);
  double s = 0;
  for (CellId c : t.cells()) s += column[c];
  return s;
}

// Per interior wall, keyed by the lineage ids of its two cells (smaller first): the densities on their sides.
std::map<std::pair<std::int64_t, std::int64_t>, std::pair<double, double>> pinByLineage(const Tissue& t) {
  const auto& pos = t.wallProperties().get<double>(NetworkStage::pinWallProperty("auxin", true));
  const auto& neg = t.wallProperties().get<double>(NetworkStage::pinWallProperty("auxin", false));
  std::map<std::pair<std::int64_t, std::int64_t>, std::pair<double, double>> out;
  for (WallId w : t.walls()) {
    std::vector<CellId> two = t.wallCells(w);
    if (two.size() != 2) continue;
    if (t.lineageId(two[1]) < t.lineageId(two[0])) std::swap(two[0], two[1]);
    const bool first_positive = networks::onPositiveSide(t, w, two[0]);
    const auto key = std::make_pair(t.lineageId(two[0]), t.lineageId(two[1]));
    const auto value = first_positive ? std::make_pair(pos[w], neg[w]) : std::make_pair(neg[w], pos[w]);
    // Two walls between the same cells hold the same densities (one interface).
    if (const auto it = out.find(key); it != out.end()) CHECK(it->second == value);
    out[key] = value;
  }
  return out;
}

}  // namespace

TEST_CASE("with_the_flux in the loop: amounts conserved across growth and divisions, PIN on the walls",
          "[sim][network][pin]") {
  Simulation sim = Simulation::fromYaml(kFluxConfig + "time: {end: 6, dt: 0.5}\n");
  const double a0 = sumProperty(sim.tissue(), "auxin_amount");
  const std::size_t cells0 = sim.tissue().numCells();
  // Before the first solve every wall side holds pin.initial.
  for (const auto& [cells, sides] : pinByLineage(sim.tissue())) CHECK(sides == std::make_pair(0.2, 0.2));
  sim.run();
  const Tissue& t = sim.tissue();
  CHECK(t.numCells() > cells0);
  CHECK(std::abs(sumProperty(t, "auxin_amount") - a0) <= 1e-12 * a0);
  // PIN has moved away from its start and a cell's PIN stays below the bound.
  const auto pin = pinByLineage(t);
  double largest = 0;
  for (const auto& [cells, sides] : pin) largest = std::max({largest, sides.first, sides.second});
  CHECK(largest > 2 * 0.2);  // twice the start and more than basal / decay
  GeometryCache geometry;
  geometry.require(t, kCellMeasures | GeometryQuantity::EdgeLengths);
  const auto& pos = t.wallProperties().get<double>(NetworkStage::pinWallProperty("auxin", true));
  const auto& neg = t.wallProperties().get<double>(NetworkStage::pinWallProperty("auxin", false));
  for (CellId c : t.cells()) {
    double amount = 0;
    for (WallId w : t.cellWalls(c))
      if (t.wallCells(w).size() == 2)
        amount += geometry.edge_length[w.index()] * (networks::onPositiveSide(t, w, c) ? pos[w] : neg[w]);
    CHECK(amount < 3.0);
  }
}

TEST_CASE("with_the_flux: a restart from a snapshot ends as the uninterrupted run", "[sim][network][pin][restart]") {
  Simulation straight = Simulation::fromYaml(kFluxConfig + "time: {end: 4, dt: 0.5}\n");
  straight.run();
  Simulation first = Simulation::fromYaml(kFluxConfig + "time: {end: 1, dt: 0.5}\n");
  first.run();
  ScratchDir dir;
  const std::string snapshot = (dir.path() / "half.vtu").string();
  first.writeSnapshot(snapshot);
  Simulation second = Simulation::fromYaml(kFluxConfig + "time: {end: 4, dt: 0.5}\n",
                                           {"tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot});
  second.run();
  const Tissue &a = straight.tissue(), &b = second.tissue();
  REQUIRE(a.numCells() == b.numCells());
  REQUIRE(a.numCells() > first.tissue().numCells());  // divisions after the restart
  const auto& amount_a = a.cellProperties().get<double>("auxin_amount");
  const auto& amount_b = b.cellProperties().get<double>("auxin_amount");
  std::map<std::int64_t, double> by_lineage;
  for (CellId c : a.cells()) by_lineage[a.lineageId(c)] = amount_a[c];
  std::size_t different = 0;
  for (CellId c : b.cells()) different += by_lineage.at(b.lineageId(c)) != amount_b[c] ? 1 : 0;
  CHECK(different == 0);
  const auto pa = pinByLineage(a), pb = pinByLineage(b);
  CHECK(pa == pb);  // exact
  const std::string x = (dir.path() / "x.vtu").string();
  CHECK(straight.snapshotState(x).at("network.pin") == second.snapshotState(x).at("network.pin"));
}

TEST_CASE("network.pin: dynamic models' errors at their keys", "[sim][network][pin][errors]") {
  auto error = [](const std::string& pin) {
    return configErrorOf([&] {
      Simulation::fromYaml("tissue: {generator: rectangular_grid}\nnetwork: {mode: transient, species: {a: {}}, "
                           "pin: {species: a, " + pin + "}}\n");
    });
  };
  ConfigError e = error("model: expression");
  CHECK(e.keyPath() == "network.pin.model");
  e = error("model: expression, expression: \"1 - pin * q\"");
  CHECK(e.keyPath() == "network.pin.expression");
  CHECK_THAT(e.what(), Catch::Contains("q"));
  e = error("model: with_the_flux, bounded: true, total: 0");
  CHECK(e.keyPath() == "network.pin.bounded");
  e = error("model: with_the_flux, flux_exponent: 0.5");
  CHECK(e.keyPath() == "network.pin.flux_exponent");
}

TEST_CASE("The PIN walls file beside a snapshot: up_the_gradient against its formula", "[sim][network][pin][output]") {
  // rate 0: no transport, the allocation of the initial gradient.
  Simulation sim = Simulation::fromYaml(R"(
tissue: {generator: hexagonal_grid, hexagonal_grid: {nx: 5, ny: 4}}
network:
  mode: transient
  species: {auxin: {initial: "1 + 0.3 * x + 0.1 * y * y"}}
  pin: {species: auxin, rate: 0, base: 2, total: 1.5, saturation: 0.2}
time: {end: 1, dt: 1}
)");
  ScratchDir dir;
  const std::string snapshot = (dir.path() / "tissue_000000.vtu").string();
  sim.writeSnapshot(snapshot);
  const io::WallsFile f = io::readWallsVtu((dir.path() / "tissue_000000.pin.vtu").string());
  const Tissue& t = sim.tissue();
  REQUIRE(f.wall_id.size() == t.numWalls());
  GeometryCache g;
  g.require(t, kCellMeasures | GeometryQuantity::EdgeLengths);
  const auto& c = t.cellProperties().get<double>("auxin");
  std::map<std::int64_t, CellId> by_lineage;
  for (CellId cell : t.cells()) by_lineage[t.lineageId(cell)] = cell;
  // D_i = kappa + sum over i's interior walls of L f(c_neighbour), f = 2^c.
  auto denominator = [&](CellId i) {
    double d = 0.2;
    for (WallId w : t.cellWalls(i))
      for (CellId j : t.wallCells(w))
        if (j != i) d += g.edge_length[w.index()] * std::pow(2.0, c[j]);
    return d;
  };
  const auto& pin_ij = f.arrays.scalars.at("pin_ij");
  const auto& pin_ji = f.arrays.scalars.at("pin_ji");
  const auto& cell_i = f.arrays.scalars.at("cell_i");
  const auto& cell_j = f.arrays.scalars.at("cell_j");
  const auto& net = f.arrays.vectors.at("pin_net");
  std::size_t interior = 0;
  for (std::size_t k = 0; k < f.wall_id.size(); ++k) {
    const WallId w(static_cast<Index>(f.wall_id[k]));
    const std::vector<CellId> two = t.wallCells(w);
    if (two.size() != 2) {
      CHECK(cell_j[k] == -1);
      CHECK(pin_ij[k] == 0);
      continue;
    }
    ++interior;
    const CellId i = by_lineage.at(static_cast<std::int64_t>(cell_i[k]));
    const CellId j = by_lineage.at(static_cast<std::int64_t>(cell_j[k]));
    CHECK(t.lineageId(i) < t.lineageId(j));
    CHECK(pin_ij[k] == Approx(1.5 * std::pow(2.0, c[j]) / denominator(i)).epsilon(1e-12));
    CHECK(pin_ji[k] == Approx(1.5 * std::pow(2.0, c[i]) / denominator(j)).epsilon(1e-12));
    // pin_net: (pin_ij - pin_ji) along the wall's unit normal from i into j.
    const auto v = t.topology().edgeVertices(EdgeId(w.index()));
    const Vec3 a = t.position(v[0]), b = t.position(v[1]);
    const Vec3 n = net[k] / (pin_ij[k] - pin_ji[k]);
    CHECK(n.norm() == Approx(1.0));
    CHECK(std::abs(n.dot(b - a)) < 1e-12);
    CHECK(n.dot(0.5 * (a + b) - cellCentroid(t, i)) > 0);
  }
  CHECK(interior > 20);
}

TEST_CASE("The PIN walls file holds the dynamic densities of the walls", "[sim][network][pin][output]") {
  Simulation sim = Simulation::fromYaml(kFluxConfig + "time: {end: 2, dt: 0.5}\n");
  sim.run();
  ScratchDir dir;
  sim.writeSnapshot((dir.path() / "end.vtu").string());
  const io::WallsFile f = io::readWallsVtu((dir.path() / "end.pin.vtu").string());
  const auto pin = pinByLineage(sim.tissue());
  std::size_t interior = 0;
  for (std::size_t k = 0; k < f.wall_id.size(); ++k) {
    if (f.arrays.scalars.at("cell_j")[k] < 0) continue;
    ++interior;
    const auto key = std::make_pair(static_cast<std::int64_t>(f.arrays.scalars.at("cell_i")[k]),
                                    static_cast<std::int64_t>(f.arrays.scalars.at("cell_j")[k]));
    CHECK(pin.at(key) == std::make_pair(f.arrays.scalars.at("pin_ij")[k], f.arrays.scalars.at("pin_ji")[k]));
  }
  CHECK(interior >= pin.size());  // two walls between the same cells share a key
}

TEST_CASE("canalization_2d.yaml: a file of high-PIN walls joins the source to the sink",
          "[sim][network][pin][configs]") {
  Simulation sim = Simulation::fromFile(tessella::sim::test::sourcePath("configs/canalization_2d.yaml"));
  sim.run();
  const Tissue& t = sim.tissue();
  GeometryCache g;
  g.require(t, kCellMeasures | GeometryQuantity::EdgeLengths);
  const auto& pos = t.wallProperties().get<double>(NetworkStage::pinWallProperty("auxin", true));
  const auto& neg = t.wallProperties().get<double>(NetworkStage::pinWallProperty("auxin", false));
  std::size_t channel = 0, high = 0, interior = 0;
  for (WallId w : t.walls()) {
    const std::vector<CellId> two = t.wallCells(w);
    if (two.size() != 2) continue;
    ++interior;
    // The side of the cell on the left (smaller x) and of the cell on the right.
    const Vec3 a = cellCentroid(t, two[0]), b = cellCentroid(t, two[1]);
    const bool first_left = a.x() < b.x();
    const double pa = networks::onPositiveSide(t, w, two[0]) ? pos[w] : neg[w];
    const double pb = networks::onPositiveSide(t, w, two[1]) ? pos[w] : neg[w];
    const double left = first_left ? pa : pb, right = first_left ? pb : pa;
    const double bound = 2.0 / g.edge_length[w.index()];  // total / L: all of a cell's PIN on this wall
    if (std::max(pa, pb) > 0.75 * bound) ++high;
    // The walls between the source's row of cells (4 < y < 5), from the source to the sink.
    if (std::abs(a.y() - b.y()) < 1e-9 && a.y() > 4 && a.y() < 5) {
      ++channel;
      CHECK(left > 0.75 * bound);   // PIN points from the source toward the sink
      CHECK(right < 0.05 * bound);
    }
  }
  CHECK(channel == 11);
  CHECK(high < 15);  // the channel, and a few walls into the sink
  CHECK(interior > 150);
}
