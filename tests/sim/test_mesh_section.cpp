// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <filesystem>

#include "tessella/sim/config/config_loader.hpp"
#include "tessella/sim/run/run.hpp"
#include "tessella/sim/sections/mesh_section.hpp"
#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/sim/sections/tessella_schema.hpp"
#include "test_support.hpp"

using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using Catch::Matchers::Contains;

namespace {
Config load(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  return loadConfigString(yaml, overrides, tessellaSchema(), "simulation", "<string>", ".");
}
}  // namespace

TEST_CASE("mesh: defaults are MeshOptions' defaults, no mesh output", "[sim][config][mesh]") {
  const Config c = load("tissue: {generator: hexagonal_grid}\n");
  const MeshSpec m = readMeshSection(c);
  const tessella::mesh::MeshOptions defaults;
  CHECK(m.options.min_angle_degrees == defaults.min_angle_degrees);
  CHECK(m.options.max_edge_length == defaults.max_edge_length);
  CHECK(m.options.max_volume == defaults.max_volume);
  CHECK(m.options.radius_edge_ratio == defaults.radius_edge_ratio);
  CHECK(m.options.min_dihedral_degrees == defaults.min_dihedral_degrees);
  CHECK(m.options.tolerance == defaults.tolerance);
  CHECK_FALSE(m.output);
  CHECK(m.every == 0);
}

TEST_CASE("mesh: every key reaches its MeshOptions field", "[sim][config][mesh]") {
  const Config c = load(
      "tissue: {generator: hexagonal_grid}\n"
      "mesh:\n  max_edge_length: 0.25\n  min_angle: 25\n  max_volume: 0.01\n  radius_edge_ratio: 1.2\n"
      "  min_dihedral_angle: 12\n  tolerance: 1.0e-9\n  output: true\n  every: 3\n");
  const MeshSpec m = readMeshSection(c);
  CHECK(m.options.max_edge_length == 0.25);
  CHECK(m.options.min_angle_degrees == 25.0);
  CHECK(m.options.max_volume == 0.01);
  CHECK(m.options.radius_edge_ratio == 1.2);
  CHECK(m.options.min_dihedral_degrees == 12.0);
  CHECK(m.options.tolerance == 1e-9);
  CHECK(m.output);
  CHECK(m.every == 3);
  CHECK(meshOptionsFromConfig(c).max_edge_length == 0.25);
}

TEST_CASE("mesh: out-of-range values are errors at their key", "[sim][config][mesh]") {
  const std::string base = "tissue: {generator: hexagonal_grid}\n";
  struct Case {
    std::string override_, key;
  };
  for (const Case& k : {Case{"mesh.min_angle=40", "mesh.min_angle"}, Case{"mesh.max_edge_length=-1", "mesh.max_edge_length"},
                        Case{"mesh.radius_edge_ratio=1", "mesh.radius_edge_ratio"},
                        Case{"mesh.min_dihedral_angle=70", "mesh.min_dihedral_angle"},
                        Case{"mesh.tolerance=0.001", "mesh.tolerance"}, Case{"mesh.every=0", "mesh.every"},
                        Case{"mesh.max_volume=-0.5", "mesh.max_volume"}}) {
    INFO(k.override_);
    const ConfigError e = configErrorOf([&] { load(base, {k.override_}); });
    CHECK_THAT(e.what(), Contains(k.key));
  }
}

TEST_CASE("mesh: the mesh series name cannot be the tissue series name", "[sim][config][mesh]") {
  const Config c = load("tissue: {generator: hexagonal_grid}\noutput: {name: mesh}\nmesh: {output: true}\n");
  const ConfigError e = configErrorOf([&] { readMeshSection(c); });
  CHECK_THAT(e.what(), Contains("output.name"));
}

namespace {
/// Runs a hexagonal-grid config with mesh.output into a scratch directory.
tessella::sim::PreparedRun runWithMesh(const std::string& dir, const std::string& extra) {
  const std::string yaml = "rng_seed: 1\ntissue: {generator: hexagonal_grid, hexagonal_grid: {nx: 3, ny: 3}}\n"
                           "time: {end: 4, dt: 1}\nmesh: {output: true, every: 2, max_edge_length: 0.5}\n" +
                           extra;
  PreparedRun run = PreparedRun::prepare(loadSimulationConfigString(yaml), RunOptions{dir, false});
  run.execute();
  return run;
}
}  // namespace

TEST_CASE("mesh.output writes the mesh series beside the tissue series", "[sim][run][mesh]") {
  namespace fs = std::filesystem;
  tessella::sim::test::ScratchDir scratch;
  SECTION("a still tissue is meshed once") {
    const PreparedRun run = runWithMesh(scratch / "still", "");
    CHECK(run.meshSnapshots() == expectedSnapshots(4, 2));  // steps 0, 2, 4
    CHECK(run.meshesBuilt() == 1);
    for (const char* f : {"mesh.pvd", "mesh_walls.pvd", "mesh_000000.vtu", "mesh_000002.vtu", "mesh_walls_000002.vtu"})
      CHECK(fs::exists(fs::path(scratch / "still") / f));
    CHECK(run.snapshots() == 5);  // the tissue series keeps output.every = 1
  }
  SECTION("a growing tissue is remeshed at every mesh snapshot") {
    const PreparedRun run =
        runWithMesh(scratch / "grow", "growth: {field: uniform, uniform: {rate: 0.1, center: [0, 0, 0]}}\n");
    CHECK(run.meshSnapshots() == 3);
    CHECK(run.meshesBuilt() == 3);
  }
  SECTION("without mesh.output no mesh file is written") {
    PreparedRun run = PreparedRun::prepare(
        loadSimulationConfigString("tissue: {generator: hexagonal_grid}\ntime: {end: 1}\n"), RunOptions{scratch / "none", false});
    run.execute();
    CHECK(run.meshSnapshots() == 0);
    CHECK_FALSE(fs::exists(fs::path(scratch / "none") / "mesh.pvd"));
  }
}

TEST_CASE("mesh.max_elements: a mesh the sizes make too large is refused before anything is written",
          "[sim][config][mesh]") {
  namespace fs = std::filesystem;
  CHECK(readMeshSection(load("tissue: {generator: hexagonal_grid}\n")).options.max_elements ==
        tessella::mesh::kDefaultMaxElements);
  CHECK(readMeshSection(load("tissue: {generator: hexagonal_grid}\nmesh: {max_elements: 0}\n")).options.max_elements ==
        0);
  tessella::sim::test::ScratchDir scratch;
  const std::string out = scratch / "out";
  // A steady diffusion meshes at the first step only: the limit is checked when the run is prepared.
  const std::string config = scratch.write(
      "tiny.yaml", "tissue: {generator: rectangular_grid}\n"
                   "diffusion: {mode: steady, dirichlet: \"x_min=1, x_max=0\"}\n"
                   "mesh: {max_edge_length: 1.0e-5}\ntime: {end: 1}\n");
  ConfigError e =
      configErrorOf([&] { PreparedRun::prepare(loadSimulationConfigFile(config), RunOptions{out, false}); });
  CHECK(e.keyPath() == "mesh.max_edge_length");
  CHECK_THAT(e.what(), Contains("tiny.yaml:3:") && Contains("max_edge_length = 1e-05") &&
                           Contains("triangles on a tissue of total area 100") && Contains("max_elements = 2e+07"));
  CHECK_FALSE(fs::exists(out));
  // mesh.output alone meshes too; the limit is the key's.
  e = configErrorOf([&] {
    PreparedRun::prepare(
        loadSimulationConfigString("tissue: {generator: rectangular_grid}\n"
                                   "mesh: {output: true, max_edge_length: 0.1, max_elements: 1000}\n"),
        RunOptions{out, false});
  });
  CHECK_THAT(e.what(), Contains("max_elements = 1000"));
  CHECK_FALSE(fs::exists(out));
  // Raised, the same run goes ahead.
  PreparedRun::prepare(loadSimulationConfigString("tissue: {generator: rectangular_grid}\n"
                                                  "mesh: {output: true, max_edge_length: 0.1, max_elements: 0}\n"),
                       RunOptions{out, false});
}
