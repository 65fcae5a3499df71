// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Several species in one diffusion stage (diffusion.species_map) and reaction
// terms from YAML expressions: the same results as separate single-species
// runs, the exact balance of a linear reaction A -> B and its convergence to
// exp(-k t), the config errors, and the entry-map machinery of the schema.

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "tessella/sim/config/config_loader.hpp"
#include "tessella/sim/run/run_record.hpp"
#include "tessella/sim/sections/tessella_schema.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/coupling_stages.hpp"
#include "tessella/tissue/geometry.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using tessella::sim::test::sourcePath;

namespace {

const FieldMesh& fieldMeshOf(const Simulation& sim) {
  for (std::size_t i = 0; i < sim.numStages(); ++i)
    if (const auto* s = dynamic_cast<const MeshFieldStage*>(&sim.stage(i))) return *s->fieldMesh();
  throw std::logic_error("no solver stage with a mesh");
}

const DiffusionStage& diffusionOf(const Simulation& sim) {
  for (std::size_t i = 0; i < sim.numStages(); ++i)
    if (const auto* s = dynamic_cast<const DiffusionStage*>(&sim.stage(i))) return *s;
  throw std::logic_error("no diffusion stage");
}

// A growing, dividing Voronoi sheet (no gate: the tissue does not depend on
// the fields, so runs with different species see the same tissues).
const std::string kTissue =
    "rng_seed: 3\n"
    "tissue: {generator: voronoi, voronoi: {domain: rectangle, count: 12, rectangle: {min: [0, 0], max: [4, 3]}}}\n"
    "growth: {field: uniform, uniform: {rate: 0.08}}\n"
    "division: {rule: main_axis, threshold: fixed, size: 1.3}\n"
    "mesh: {max_edge_length: 0.6}\n"
    "time: {end: 2, dt: 0.5}\n";

// The keys of two different species, written once at the top of `diffusion`
// (single form) and once in a species_map entry.
const std::string kA =
    "diffusivity: 0.4, decay: 0.2, initial: 1, source: {rate: 3, center: [0, 1.5, 0], radius: 1.2}";
const std::string kB = "diffusivity: 1.5, production: 0.1, dirichlet: \"x_max=2\", robin: \"y_min=0.3\", exterior: 1";

}  // namespace

TEST_CASE("two uncoupled species in one stage give exactly what two single-species runs give", "[sim][species]") {
  for (const char* scheme : {"implicit_euler", "crank_nicolson"}) {
    INFO(scheme);
    const std::string shared = std::string("mode: transient, scheme: ") + scheme + ", dt: 0.25";
    Simulation both = Simulation::fromYaml(kTissue + "diffusion: {" + shared + ", species_map: {A: {" + kA +
                                           "}, B: {" + kB + "}}}\n");
    Simulation a = Simulation::fromYaml(kTissue + "diffusion: {" + shared + ", species: A, " + kA + "}\n");
    Simulation b = Simulation::fromYaml(kTissue + "diffusion: {" + shared + ", species: B, " + kB + "}\n");
    both.run();
    a.run();
    b.run();
    REQUIRE(both.tissue().numCells() > 12);  // it divided
    REQUIRE(both.tissue().numCells() == a.tissue().numCells());
    const FieldMesh& fm = fieldMeshOf(both);
    for (const auto& [name, single] : {std::pair<std::string, const Simulation*>{"A", &a}, {"B", &b}}) {
      INFO("species " << name);
      const Eigen::VectorXd& u = fm.field(name);
      const Eigen::VectorXd& v = fieldMeshOf(*single).field(name);
      REQUIRE(u.size() == v.size());
      CHECK((u - v).cwiseAbs().maxCoeff() <= 1e-12 * std::max(1.0, v.cwiseAbs().maxCoeff()));
      const auto& avg = both.tissue().cellProperties().get<double>(name);
      const auto& amount = both.tissue().cellProperties().get<double>(name + "_amount");
      const auto& avg1 = single->tissue().cellProperties().get<double>(name);
      const auto& amount1 = single->tissue().cellProperties().get<double>(name + "_amount");
      for (CellId c : both.tissue().cells()) {
        CHECK(avg[c] == Approx(avg1[c]).margin(1e-12));
        CHECK(amount[c] == Approx(amount1[c]).margin(1e-12));
      }
    }
    CHECK(diffusionOf(both).totalAmount(0) == Approx(diffusionOf(a).totalAmount()).epsilon(1e-12));
    CHECK(diffusionOf(both).totalAmount(1) == Approx(diffusionOf(b).totalAmount()).epsilon(1e-12));
  }
}

TEST_CASE("a linear reaction A -> B: A + B conserved, A decays as exp(-k t) at the scheme's order",
          "[sim][species]") {
  // Zero-flux boundaries: 1^T K = 0, so the totals S of the semi-implicit
  // scheme (reaction explicit, docs/solvers.md) obey S_A' = -k S_A discretised
  // by explicit Euler (implicit_euler) or by Adams-Bashforth 2 after one Euler
  // step per solve (crank_nicolson), and S_A + S_B changes by round-off only.
  const double k = 0.8, T = 2.0, A0 = 1.0;
  const auto run = [&](const std::string& scheme, double h) {
    Simulation sim = Simulation::fromYaml(
        "tissue: {generator: hexagonal_grid, hexagonal_grid: {nx: 3, ny: 3}}\n"
        "time: {end: 2, dt: 0.5}\n"
        "diffusion: {mode: transient, scheme: " + scheme + ", dt: " + std::to_string(h) +
        ", species_map: {A: {initial: 1, diffusivity: 0.3, reaction: \"-0.8*A\"}, "
        "B: {initial: 0.25, diffusivity: 2, reaction: \"0.8*A\"}}}\n");
    const double area = totalMeasure(sim.tissue());
    sim.run();
    const DiffusionStage& d = diffusionOf(sim);
    CHECK(d.totalAmount(0) + d.totalAmount(1) == Approx(area * (A0 + 0.25)).epsilon(1e-13));
    return std::pair<double, double>{d.totalAmount(0) / area, area};
  };
  const double exact = A0 * std::exp(-k * T);
  SECTION("implicit Euler: first order, error ~ k^2 T h / 2 exp(-k T)") {
    const auto [coarse, area] = run("implicit_euler", 0.05);
    const auto [fine, area2] = run("implicit_euler", 0.025);
    // The scheme's own closed form: (1 - k h)^(T / h).
    CHECK(coarse == Approx(std::pow(1 - k * 0.05, T / 0.05)).epsilon(1e-12));
    const double e1 = std::abs(coarse - exact), e2 = std::abs(fine - exact);
    CHECK(e1 < 0.6 * k * k * T * 0.05 * exact);
    CHECK(e1 > 0.4 * k * k * T * 0.05 * exact);
    CHECK(e1 / e2 == Approx(2.0).epsilon(0.05));
  }
  SECTION("Crank-Nicolson with extrapolated reaction: second order") {
    const auto [coarse, area] = run("crank_nicolson", 0.05);
    const auto [fine, area2] = run("crank_nicolson", 0.025);
    // Leading errors (relative): one Euler step per solve, (k h)^2 / 2 each
    // (setState starts the extrapolation afresh), and AB2's 5/12 k^3 h^2 T.
    const double h = 0.05, solves = T / 0.5;
    const double bound = (solves * k * k * h * h / 2 + 5.0 / 12.0 * k * k * k * h * h * T) * exact;
    const double e1 = std::abs(coarse - exact), e2 = std::abs(fine - exact);
    CHECK(e1 < 1.5 * bound);
    CHECK(e1 / e2 == Approx(4.0).epsilon(0.1));
  }
}

TEST_CASE("a nonlinear reaction from YAML: the logistic equation in a single species", "[sim][species]") {
  // u' = u (1 - u) from u0 = 0.1, uniform (zero flux): u = 1 / (1 + 9 e^-t).
  Simulation sim = Simulation::fromYaml(
      "tissue: {generator: rectangular_grid, rectangular_grid: {nx: 3, ny: 2}}\n"
      "time: {end: 3, dt: 0.5}\n"
      "diffusion: {mode: transient, scheme: crank_nicolson, dt: 0.01, species: m, initial: 0.1, "
      "reaction: \"m*(1-m)\"}\n");
  sim.run();
  const double exact = 1.0 / (1.0 + 9.0 * std::exp(-3.0));
  const Eigen::VectorXd& m = fieldMeshOf(sim).field("m");
  CHECK(std::abs(m.maxCoeff() - exact) < 1e-4);
  CHECK(std::abs(m.minCoeff() - exact) < 1e-4);
  for (CellId c : sim.tissue().cells()) CHECK(sim.tissue().cellProperties().get<double>("m")[c] == Approx(exact).epsilon(1e-4));
}

TEST_CASE("species_map errors name the key, the file, the line and the column", "[sim][species][errors]") {
  const auto error = [](const std::string& yaml) {
    return configErrorOf([&] { Simulation::fromYaml("tissue: {generator: rectangular_grid}\n" + yaml); });
  };
  SECTION("an unknown key in an entry: did you mean") {
    const ConfigError e = error(
        "diffusion:\n  mode: transient\n  species_map:\n    A:\n      diffusivty: 1\n");
    CHECK(e.keyPath() == "diffusion.species_map.A.diffusivty");
    CHECK(e.where().line == 6);
    CHECK(e.where().column == 7);
    CHECK_THAT(e.what(), Catch::Contains("did you mean 'diffusivity'?"));
  }
  SECTION("bad and duplicate names") {
    ConfigError e = error("diffusion:\n  mode: transient\n  species_map:\n    2A: {}\n");
    CHECK(e.keyPath() == "diffusion.species_map.2A");
    CHECK(e.where().line == 5);
    CHECK(e.where().column == 5);
    CHECK_THAT(e.what(), Catch::Contains("bad species name '2A'"));
    e = error("diffusion:\n  mode: transient\n  species_map:\n    A-b: {}\n");
    CHECK_THAT(e.what(), Catch::Contains("bad species name 'A-b'"));
    e = error("diffusion:\n  mode: transient\n  species_map:\n    A: {}\n    A: {decay: 1}\n");
    CHECK(e.keyPath() == "diffusion.species_map.A");
    CHECK(e.where().line == 6);
    CHECK_THAT(e.what(), Catch::Contains("duplicate key"));
    // A species whose outputs are another's.
    e = error("diffusion:\n  mode: transient\n  species_map:\n    A: {}\n    A_amount: {}\n");
    CHECK(e.keyPath() == "diffusion.species_map.A_amount");
    CHECK(e.where().line == 6);
    CHECK_THAT(e.what(), Catch::Contains("'A_amount', which another species writes"));
  }
  SECTION("an entry that is not a mapping, a value out of range") {
    ConfigError e = error("diffusion:\n  mode: transient\n  species_map:\n    A: 3\n");
    CHECK(e.keyPath() == "diffusion.species_map.A");
    CHECK_THAT(e.what(), Catch::Contains("expected a section"));
    e = error("diffusion:\n  mode: transient\n  species_map:\n    A: {decay: -1}\n");
    CHECK(e.keyPath() == "diffusion.species_map.A.decay");
    CHECK(e.where().line == 5);
    CHECK_THAT(e.what(), Catch::Contains("out of range"));
  }
  SECTION("a reaction with a syntax error, with an unknown variable") {
    ConfigError e = error(
        "diffusion:\n  mode: transient\n  species_map:\n    A: {reaction: \"-A*\"}\n    B: {}\n");
    CHECK(e.keyPath() == "diffusion.species_map.A.reaction");
    CHECK(e.where().line == 5);
    CHECK(e.where().column == 19);
    CHECK_THAT(e.what(), Catch::Contains("\"-A*\""));
    e = error("diffusion:\n  mode: transient\n  species_map:\n    A: {}\n    B:\n      reaction: A - C\n");
    CHECK(e.keyPath() == "diffusion.species_map.B.reaction");
    CHECK(e.where().line == 7);
    CHECK(e.where().column == 17);
    CHECK_THAT(e.what(), Catch::Contains("near 'C'"));
    CHECK_THAT(e.what(), Catch::Contains("the variables are the species names"));
    // The single-species form knows its own species only.
    e = error("diffusion: {mode: transient, species: m, reaction: \"u*(1-u)\"}\n");
    CHECK(e.keyPath() == "diffusion.reaction");
    CHECK_THAT(e.what(), Catch::Contains("near 'u'"));
  }
  SECTION("per-species keys at the top of diffusion with species_map") {
    ConfigError e = error("diffusion:\n  mode: transient\n  decay: 1\n  species_map: {A: {}}\n");
    CHECK(e.keyPath() == "diffusion.decay");
    CHECK(e.where().line == 4);
    CHECK_THAT(e.what(), Catch::Contains("give it per species: diffusion.species_map.A.decay"));
    e = error("diffusion:\n  mode: transient\n  reaction: \"-A\"\n  species_map: {A: {}}\n");
    CHECK(e.keyPath() == "diffusion.reaction");
  }
  SECTION("a division gate on a species that is not declared") {
    const ConfigError e = error(
        "division: {rule: main_axis, gate: {field: C}}\n"
        "diffusion: {mode: transient, species_map: {A: {}, B: {}}}\n");
    CHECK(e.keyPath() == "division.gate.field");
    CHECK_THAT(e.what(), Catch::Contains("known: A, A_amount, B, B_amount"));
  }
  SECTION("overrides reach entries, checked the same way") {
    const std::string yaml = "tissue: {generator: rectangular_grid}\ndiffusion: {mode: transient, species_map: {A: {}}}\n";
    Config c = loadConfigString(yaml, {"diffusion.species_map.B.decay=0.5"}, tessellaSchema());
    CHECK(c.entryNames("diffusion.species_map") == std::vector<std::string>{"A", "B"});
    CHECK(c.getFloat("diffusion.species_map.B.decay") == 0.5);
    CHECK(c.getFloat("diffusion.species_map.A.diffusivity") == 1.0);  // defaults per entry
    const ConfigError e = configErrorOf(
        [&] { loadConfigString(yaml, {"diffusion.species_map.A.decy=1"}, tessellaSchema()); });
    CHECK_THAT(e.what(), Catch::Contains("did you mean 'diffusion.species_map.A.decay'?"));
  }
}

TEST_CASE("species_map entries are written to run.yaml and read back the same", "[sim][species]") {
  const std::string yaml =
      "tissue: {generator: rectangular_grid}\n"
      "diffusion: {mode: transient, species_map: {Zed: {decay: 0.5, reaction: \"-Zed*Alpha\"}, Alpha: }}\n";
  const Config c = loadConfigString(yaml, {}, tessellaSchema());
  const std::string record = resolvedConfigYaml(c);
  CHECK(record.find("Zed:") < record.find("Alpha:"));  // the order given, not sorted
  const Config again = loadConfigString(record, {}, tessellaSchema());
  CHECK(again.entryNames("diffusion.species_map") == std::vector<std::string>{"Zed", "Alpha"});
  CHECK(again.getString("diffusion.species_map.Zed.reaction") == "-Zed*Alpha");
  CHECK(again.getFloat("diffusion.species_map.Alpha.decay") == 0.0);
  CHECK(resolvedConfigYaml(again) == record);
}

TEST_CASE("the schema's entry maps: template lookups and declaration checks", "[sim][schema]") {
  const Schema& s = tessellaSchema();
  CHECK(s.isEntryMap("diffusion.species_map"));
  CHECK(s.templatePath("diffusion.species_map.A.source.rate") == "diffusion.species_map.<name>.source.rate");
  REQUIRE(s.findKey("diffusion.species_map.X1.decay"));
  CHECK(s.findKey("diffusion.species_map.X1.decay")->path == "diffusion.species_map.<name>.decay");
  CHECK(s.childNames("diffusion.species_map") == std::vector<std::string>{"<name>"});
  Schema bad;
  bad.section("m", "a map").entryMap("thing");
  CHECK_THROWS_AS(bad.key("m.x", ValueType::Float, "a key directly in a map"), std::logic_error);
  CHECK_THROWS_AS(bad.section("m.y", "a section that is not the entry"), std::logic_error);
}

TEST_CASE("A -> B on a growing, dividing sheet: remeshing conserves each species' amount", "[sim][species]") {
  Simulation sim = Simulation::fromYaml(
      kTissue + "diffusion: {mode: transient, scheme: crank_nicolson, dt: 0.1, species_map: "
                "{A: {initial: 1, diffusivity: 0.3, reaction: \"-0.8*A\"}, B: {diffusivity: 2, reaction: \"0.8*A\"}}}\n");
  const double area0 = totalMeasure(sim.tissue());
  const std::size_t cells0 = sim.tissue().numCells();
  sim.run();
  CHECK(sim.tissue().numCells() > cells0);
  CHECK(fieldMeshOf(sim).remeshes() > 4);
  const DiffusionStage& d = diffusionOf(sim);
  CHECK(d.totalAmount(0) + d.totalAmount(1) == Approx(area0).epsilon(1e-9));
  double a = 0, b = 0;
  for (CellId c : sim.tissue().cells()) {
    a += sim.tissue().cellProperties().get<double>("A_amount")[c];
    b += sim.tissue().cellProperties().get<double>("B_amount")[c];
  }
  CHECK(a == Approx(d.totalAmount(0)).epsilon(1e-9));
  CHECK(b == Approx(d.totalAmount(1)).epsilon(1e-9));
  // The total of A follows the same recurrence as on a fixed sheet (1^T K = 0
  // on every mesh, the transfer keeps the amount): within AB2's error of exp(-0.8 t).
  CHECK(d.totalAmount(0) / area0 == Approx(std::exp(-0.8 * 2.0)).epsilon(0.01));
}

TEST_CASE("activator_inhibitor_2d.yaml: peaks form only when the inhibitor diffuses much faster", "[sim][species][configs]") {
  // Gierer-Meinhardt about a = h = 2: a Turing instability needs
  // Dh / Da > 11.7 (the config has 40); with Dh = Da the homogeneous state is
  // stable and the source's bump stays small.
  const auto spread = [](const std::vector<std::string>& overrides) {
    Simulation sim = Simulation::fromFile(sourcePath("configs/activator_inhibitor_2d.yaml"), overrides);
    sim.run();
    const Eigen::VectorXd& a = fieldMeshOf(sim).field("activator");
    return std::pair<double, std::size_t>{a.maxCoeff() - a.minCoeff(), sim.tissue().numCells()};
  };
  const auto [turing, cells] = spread({});
  const auto [stable, cells_stable] = spread({"diffusion.species_map.inhibitor.diffusivity=0.01"});
  CHECK(turing > 3.0);            // peaks well above and troughs well below a = 2
  CHECK(stable < 0.25 * turing);
  CHECK(cells > 40);              // cells in the peaks divided
}

TEST_CASE("a reaction rate that is not finite stops the run naming the key and the values",
          "[sim][species][errors]") {
  Simulation sim = Simulation::fromYaml(
      "tissue: {generator: rectangular_grid, rectangular_grid: {nx: 2, ny: 1}}\n"
      "time: {end: 1, dt: 0.5}\n"
      "diffusion: {mode: transient, species_map: {a: {initial: 1, reaction: \"a^2 / h\"}, h: {initial: 0}}}\n");
  try {
    sim.run();
    FAIL("expected an error");
  } catch (const SimulationError& e) {
    CHECK_THAT(e.what(), Catch::Contains("stage 'diffusion'"));
    CHECK_THAT(e.what(), Catch::Contains("diffusion.species_map.a.reaction: \"a^2 / h\" gave inf at a = 1, h = 0"));
  }
}

TEST_CASE("the single-species name keeps its rule; a reaction needs a name muparser accepts", "[sim][species][errors]") {
  const std::string base = "tissue: {generator: rectangular_grid}\n";
  CHECK_NOTHROW(Simulation::fromYaml(base + "diffusion: {mode: transient, species: 2u}\n"));
  ConfigError e = configErrorOf([&] { Simulation::fromYaml(base + "diffusion: {mode: transient, species: u-v}\n"); });
  CHECK(e.keyPath() == "diffusion.species");
  CHECK_THAT(e.what(), Catch::Contains("letters, digits and '_', got 'u-v'"));
  e = configErrorOf([&] { Simulation::fromYaml(base + "diffusion: {mode: transient, species: 2u, reaction: \"-2u\"}\n"); });
  CHECK(e.keyPath() == "diffusion.reaction");
}
