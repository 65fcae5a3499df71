// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Keys that assume a dimension or embedding of the tissue are checked against
// the tissue the config builds (or restarts from) when the config is read:
// a mismatch is a ConfigError naming the key and both dimensions, and a run
// writes nothing.

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "tessella/io/vtu.hpp"
#include "tessella/sim/run/run.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/generators/grids.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace tessella;
using namespace tessella::sim;
using Catch::Matchers::Contains;
using tessella::sim::test::configErrorOf;
using tessella::sim::test::ScratchDir;

namespace {

const std::string kGrid =
    "tissue: {generator: rectangular_grid, rectangular_grid: {nx: 3, ny: 2}}\n";
const std::string kBox = "tissue: {generator: box_grid, box_grid: {nx: 2, ny: 2, nz: 2}}\n";
const std::string kDome = "tissue: {generator: dome, dome: {count: 20}}\n";

ConfigError errorOf(const std::string& yaml, const std::string& base = ".") {
  return configErrorOf([&] { Simulation::fromYaml(yaml, {}, base); });
}

}  // namespace

TEST_CASE("elasticity models must fit the tissue's dimension", "[sim][config][dimension]") {
  ConfigError e = errorOf(kGrid + "elasticity: {model: solid, fixed: \"x_min=xyz\"}\n");
  CHECK(e.keyPath() == "elasticity.model");
  CHECK_THAT(e.what(), Contains("'solid' needs a 3D tissue; the tissue is 2D") &&
                           Contains("tissue.generator: rectangular_grid"));
  e = errorOf(kBox + "elasticity: {model: plane_stress, fixed: \"x_min=xy\"}\n");
  CHECK(e.keyPath() == "elasticity.model");
  CHECK_THAT(e.what(), Contains("'plane_stress' needs a flat 2D tissue; the tissue is 3D") &&
                           Contains("use solid"));
  e = errorOf(kDome + "elasticity: {model: plane_strain, fixed: \"x_min=xy\"}\n");
  CHECK_THAT(e.what(),
             Contains("'plane_strain' needs a flat 2D tissue; the tissue is 2D (a curved sheet"));
  // z does not exist in a plane model.
  e = errorOf(kGrid + "elasticity: {model: plane_stress, fixed: \"x_min=xyz\"}\n");
  CHECK(e.keyPath() == "elasticity.fixed");
  CHECK_THAT(e.what(), Contains("component z (on 'x_min')"));
  e = errorOf(kGrid +
              "elasticity: {model: plane_stress, fixed: \"x_min=xy\", traction_region: x_max, "
              "traction: [1, 0, 2]}\n");
  CHECK(e.keyPath() == "elasticity.traction");
  e = errorOf(kGrid +
              "elasticity: {model: plane_stress, fixed: \"x_min=xy\", stretch_region: z_max, "
              "stretch: 1}\n");
  CHECK(e.keyPath() == "elasticity.stretch_region");
  CHECK_THAT(e.what(), Contains("'z_max' needs a 3D tissue or a curved sheet"));
  // The matching combinations are fine.
  Simulation::fromYaml(kGrid + "elasticity: {model: plane_stress, fixed: \"x_min=xy\"}\n");
  Simulation::fromYaml(kBox + "elasticity: {model: solid, fixed: \"x_min=xyz, z_max=z\"}\n");
}

TEST_CASE("growth, division, diffusion, compartment and mesh keys must fit the tissue",
          "[sim][config][dimension]") {
  ConfigError e = errorOf(kBox + "growth: {field: uniform, surface: sphere}\n");
  CHECK(e.keyPath() == "growth.surface");
  CHECK_THAT(e.what(), Contains("'sphere' keeps a curved 2D sheet on a surface; the tissue is 3D"));
  e = errorOf(kGrid + "growth: {field: uniform, surface: paraboloid}\n");
  CHECK_THAT(e.what(), Contains("the tissue is 2D (flat"));
  Simulation::fromYaml(kDome + "growth: {field: uniform, surface: sphere, sphere: {radius: 5}}\n");

  e = errorOf(kGrid + "division: {rule: fixed, fixed_normal: [0, 0, 1]}\n");
  CHECK(e.keyPath() == "division.fixed_normal");
  Simulation::fromYaml(kBox + "division: {rule: fixed, fixed_normal: [0, 0, 1]}\n");

  e = errorOf(kGrid + "diffusion: {mode: steady, dirichlet: \"x_min=1, z_max=0\"}\n");
  CHECK(e.keyPath() == "diffusion.dirichlet");
  CHECK_THAT(e.what(), Contains("'z_max'") && Contains("2D (flat"));
  e = errorOf(kGrid + "diffusion: {mode: transient, species_map: {a: {flux: \"z_min=1\"}}}\n");
  CHECK(e.keyPath() == "diffusion.species_map.a.flux");
  Simulation::fromYaml(kBox + "diffusion: {mode: steady, dirichlet: \"x_min=1, z_max=0\"}\n");

  e = errorOf(kGrid + "compartments: {mode: transient, polar: {rate: 1, direction: [0, 0, 2]}}\n");
  CHECK(e.keyPath() == "compartments.polar.direction");

  e = errorOf(kGrid + "mesh: {max_volume: 0.1}\n");
  CHECK(e.keyPath() == "mesh.max_volume");
  CHECK_THAT(e.what(), Contains("applies to 3D tissues (tetrahedra) only; the tissue is 2D"));
  e = errorOf(kGrid + "mesh: {volume_method: whole_tissue}\n");
  CHECK(e.keyPath() == "mesh.volume_method");
  // Defaults written out (as run.yaml does) are fine.
  Simulation::fromYaml(
      kGrid + "mesh: {max_volume: 0, volume_method: cell_by_cell, radius_edge_ratio: 1.5}\n");
}

TEST_CASE(
    "a snapshot of another dimension than the config describes is refused and nothing is written",
    "[sim][config][dimension][run]") {
  ScratchDir dir;
  io::writeTissueVtu(boxGrid(2, 2, 2), dir / "box.vtu");
  io::writeTissueVtu(rectangularGrid(3, 2), dir / "grid.vtu");
  // A 2D config (its Voronoi rectangle kept beside the snapshot generator) restarted from a 3D
  // snapshot.
  const std::string config = dir.write("restart.yaml",
                                       "tissue:\n  generator: snapshot\n  snapshot: {file: "
                                       "box.vtu}\n  voronoi: {domain: rectangle, count: 20}\n"
                                       "growth: {field: uniform}\ntime: {end: 1, dt: 0.5}\n");
  const std::string out = dir / "out";
  ConfigError e = configErrorOf([&] {
    PreparedRun::prepare(loadSimulationConfigFile(config), RunOptions{out, false});
  });
  CHECK(e.keyPath() == "tissue.snapshot.file");
  CHECK_THAT(e.what(), Contains("restart.yaml:3") && Contains("the snapshot holds a 3D tissue") &&
                           Contains("describes a 2D one (tissue.voronoi (domain: rectangle))"));
  CHECK_FALSE(fs::exists(out));
  // The same through --set, as a restart is usually written.
  e = configErrorOf([&] {
    PreparedRun::prepare(loadSimulationConfigFile(test::sourcePath("configs/voronoi_growth.yaml"),
                                                  {"tissue.generator=snapshot",
                                                   "tissue.snapshot.file=" + (dir / "box.vtu")}),
                         RunOptions{out, false});
  });
  CHECK_THAT(e.what(), Contains("3D tissue") && Contains("2D one"));
  CHECK_FALSE(fs::exists(out));
  // The elasticity mismatch is found before output, not at step 1.
  const std::string elastic =
      dir.write("elastic.yaml",
                "tissue: {generator: snapshot, snapshot: {file: grid.vtu}}\n"
                "elasticity: {model: solid, fixed: \"x_min=xyz\"}\ntime: {end: 1, dt: 0.5}\n");
  e = configErrorOf([&] {
    PreparedRun::prepare(loadSimulationConfigFile(elastic), RunOptions{out, false});
  });
  CHECK(e.keyPath() == "elasticity.model");
  CHECK_THAT(e.what(), Contains("the tissue is 2D") && Contains("grid.vtu"));
  CHECK_FALSE(fs::exists(out));
  // A snapshot of the dimension the config describes restarts, and one with no generator section
  // too.
  loadSimulationConfigFile(config, {"tissue.snapshot.file=" + (dir / "grid.vtu")});
  loadSimulationConfigFile(
      dir.write("plain.yaml", "tissue: {generator: snapshot, snapshot: {file: box.vtu}}\n"));
}
