// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The network: section (networks/ in the loop): the example config, amounts
// conserved across growth and divisions, PIN polarity, errors at their keys.

#include <catch2/catch.hpp>

#include <cmath>

#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/network_stage.hpp"
#include "tessella/tissue/geometry.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using tessella::sim::test::sourcePath;

namespace {
double sumProperty(const Tissue& t, const std::string& name) {
  const auto& column = t.cellProperties().get<double>(name);
  double s = 0;
  for (CellId c : t.cells()) s += column[c];
  return s;
}

const NetworkStage& networkStageOf(const Simulation& sim) {
  for (std::size_t i = 0; i < sim.numStages(); ++i)
    if (const auto* s = dynamic_cast<const NetworkStage*>(&sim.stage(i))) return *s;
  throw std::logic_error("no network stage");
}
}  // namespace

TEST_CASE("auxin_network_2d.yaml: the total amount follows production and decay exactly", "[sim][network][configs]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/auxin_network_2d.yaml"));
  const Tissue& t = sim.tissue();
  const double area = totalMeasure(t);
  const double M0 = sumProperty(t, "auxin_amount");
  // Initial concentration 10 plus noise in [0, 0.5).
  CHECK(M0 > 10 * area);
  CHECK(M0 < 10.5 * area);
  sim.run();
  // Transport moves amounts between cells only, so dM/dt = p A - d M whatever the pattern.
  const double p = 0.5, d = 0.05, T = sim.time();
  const double expected = p * area / d + (M0 - p * area / d) * std::exp(-d * T);
  CHECK(sumProperty(t, "auxin_amount") == Approx(expected).epsilon(1e-6));
  CHECK(networkStageOf(sim).solves() == sim.numSteps());
  const auto& a = t.cellProperties().get<double>("auxin");
  const auto& amount = t.cellProperties().get<double>("auxin_amount");
  double lo = 1e300, hi = 0;
  for (CellId c : t.cells()) {
    CHECK(a[c] == Approx(amount[c] / cellMeasure(t, c)));
    CHECK(a[c] > 0);
    lo = std::min(lo, a[c]);
    hi = std::max(hi, a[c]);
  }
  INFO("auxin from " << lo << " to " << hi);
  // Up-the-gradient transport makes peaks from a start within 5 % of uniform.
  CHECK(hi > 2 * lo);
  CHECK(t.cellProperties().has("auxin_polarity"));
}

TEST_CASE("network.linear_solver: gmres gives KLU's accuracy on auxin_network_2d.yaml", "[sim][network][configs]") {
  auto run = [](std::vector<std::string> overrides) {
    overrides.push_back("time.end=10");
    Simulation sim = Simulation::fromFile(sourcePath("configs/auxin_network_2d.yaml"), overrides);
    sim.run();
    std::vector<double> out;
    const auto& a = sim.tissue().cellProperties().get<double>("auxin_amount");
    for (CellId c : sim.tissue().cells()) out.push_back(a[c]);
    return out;
  };
  // The reference: KLU, exact Jacobian, tolerances 1e4 times tighter than the config's (1e-6, 1e-9).
  const std::vector<double> reference = run({"network.jacobian=exact", "network.relative_tolerance=1e-10",
                                             "network.absolute_tolerance=1e-13"});
  const std::vector<double> klu = run({"network.linear_solver=klu"});
  const std::vector<double> gmres = run({"network.linear_solver=gmres"});
  auto error = [&](const std::vector<double>& y) {
    double e = 0;
    for (std::size_t k = 0; k < y.size(); ++k) e = std::max(e, std::abs(y[k] - reference[k]) / reference[k]);
    return e;
  };
  INFO("KLU error " << error(klu) << ", GMRES error " << error(gmres));
  CHECK(error(klu) < 1e-3);
  CHECK(error(gmres) < 3 * error(klu));
}

TEST_CASE("network amounts are conserved across growth and divisions", "[sim][network]") {
  Simulation sim = Simulation::fromYaml(R"(
rng_seed: 3
tissue: {generator: rectangular_grid, rectangular_grid: {nx: 6, ny: 3}}
growth: {field: anisotropic, anisotropic: {rates: [0.1, 0.05, 0]}}
division: {rule: main_axis, size: 1.3}
network:
  mode: transient
  species:
    a: {initial: "1 + 0.3 * x", permeability: 0.2}
    b: {initial: "2 + y", noise: 0.4}
  pin: {species: a, rate: 0.5, base: 2}
time: {end: 6, dt: 0.5}
)");
  const double a0 = sumProperty(sim.tissue(), "a_amount"), b0 = sumProperty(sim.tissue(), "b_amount");
  const std::size_t cells0 = sim.tissue().numCells();
  sim.run();
  CHECK(sim.tissue().numCells() > cells0);
  CHECK(std::abs(sumProperty(sim.tissue(), "a_amount") - a0) <= 1e-12 * a0);
  CHECK(std::abs(sumProperty(sim.tissue(), "b_amount") - b0) <= 1e-12 * b0);
}

TEST_CASE("PIN polarity points up the gradient of auxin", "[sim][network]") {
  // No transport (rate 0): the PIN allocation of a linear gradient along x.
  Simulation sim = Simulation::fromYaml(R"(
tissue: {generator: hexagonal_grid, hexagonal_grid: {nx: 6, ny: 6}}
network:
  mode: transient
  species: {auxin: {initial: "1 + 0.5 * x"}}
  pin: {species: auxin, rate: 0, base: 3}
time: {end: 1, dt: 1}
)");
  sim.run();
  const Tissue& t = sim.tissue();
  const auto& polarity = t.cellProperties().get<Vec3>("auxin_polarity");
  int inner = 0;
  for (CellId c : t.cells()) {
    if (t.cellNeighbors(c).size() != 6) continue;
    ++inner;
    // Six neighbours at 60 degree steps, weights 3^(0.5 x_j): the y parts cancel.
    CHECK(polarity[c].x() > 0);
    CHECK(std::abs(polarity[c].y()) < 1e-12);
  }
  CHECK(inner > 0);
}

TEST_CASE("network: errors at their keys", "[sim][network][errors]") {
  auto error = [](const std::string& yaml) {
    return configErrorOf([&] { Simulation::fromYaml("tissue: {generator: rectangular_grid}\n" + yaml); });
  };
  ConfigError e = error("network: {mode: transient, species: {a: {reaction: \"a * k\"}}}\n");
  CHECK(e.keyPath() == "network.species.a.reaction");
  CHECK_THAT(e.what(), Catch::Contains("k"));
  e = error("network: {mode: transient, species: {a: {initial: \"1 +\"}}}\n");
  CHECK(e.keyPath() == "network.species.a.initial");
  e = error("network: {mode: transient, species: {a: {}}, pin: {species: b}}\n");
  CHECK(e.keyPath() == "network.pin.species");
  CHECK_THAT(e.what(), Catch::Contains("'b' is not a species"));
  e = error("network: {mode: transient, parameters: \"k=x1\", species: {a: {}}}\n");
  CHECK(e.keyPath() == "network.parameters");
  e = error("network: {mode: transient, parameters: \"a=1\", species: {a: {}}}\n");
  CHECK(e.keyPath() == "network.parameters");
  CHECK_THAT(e.what(), Catch::Contains("'a' is named twice"));
  e = error("network: {mode: transient}\n");
  CHECK(e.keyPath() == "network.mode");
  e = error("network: {mode: transient, species: {a: {permeability: -1}}}\n");
  CHECK(e.keyPath() == "network.species.a.permeability");
  // A species named like a diffusion species: both stages would write the property `auxin`.
  e = error("diffusion: {mode: transient, species: auxin}\nnetwork: {mode: transient, species: {auxin: {}}}\n");
  CHECK(e.keyPath() == "network");
  CHECK_THAT(e.what(), Catch::Contains("'auxin' is written by both the diffusion and the network stage"));
}

TEST_CASE("network.pin: Smith et al.'s options are read into the model", "[sim][network]") {
  Simulation sim = Simulation::fromYaml(R"(
tissue: {generator: hexagonal_grid, hexagonal_grid: {nx: 4, ny: 4}}
network:
  mode: transient
  species: {auxin: {initial: 1}}
  pin: {species: auxin, total: 0.4, total_per_concentration: 0.3, efflux: saturating, efflux_saturation: 0.2}
)");
  const networks::PinTransport& pin = networkStageOf(sim).spec().model.pin;
  CHECK(pin.total == 0.4);
  CHECK(pin.total_per_concentration == 0.3);
  CHECK(pin.efflux == networks::PinEfflux::Saturating);
  CHECK(pin.efflux_saturation == 0.2);
  ConfigError e = configErrorOf([] {
    Simulation::fromYaml("tissue: {generator: rectangular_grid}\n"
                         "network: {mode: transient, species: {a: {}}, pin: {species: a, efflux: quadratic}}\n");
  });
  CHECK(e.keyPath() == "network.pin.efflux");
  e = configErrorOf([] {
    Simulation::fromYaml("tissue: {generator: rectangular_grid}\n"
                         "network: {mode: transient, species: {a: {}}, "
                         "pin: {species: a, total_per_concentration: -1}}\n");
  });
  CHECK(e.keyPath() == "network.pin.total_per_concentration");
}
