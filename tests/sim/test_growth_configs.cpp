// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The growth: and division: sections and the example configs that use them.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "tessella/growth/bump_field.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/sim/config/config_error.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/growth_stages.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using Catch::Matchers::Contains;
using tessella::sim::test::sourcePath;

namespace {

// Runs a simulation, validating the tissue and the uniqueness of lineage ids
// after every step; returns the number of divisions.
std::size_t runValidated(Simulation& sim) {
  tessella::sim::test::validateEveryStep(sim);
  sim.run();
  for (std::size_t i = 0; i < sim.numStages(); ++i)
    if (const auto* d = dynamic_cast<const DivisionStage*>(&sim.stage(i))) return d->divisions();
  return 0;
}

}  // namespace

TEST_CASE("figure17.yaml: the paper's bump run", "[sim][growth][configs]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/figure17.yaml"), {"time.end=2.0"});
  REQUIRE(sim.numStages() == 2);
  CHECK(sim.stage(0).name() == "growth");
  CHECK(sim.stage(1).name() == "division");
  const Tissue start = sim.tissue();
  runValidated(sim);
  // Boundary vertices move with the field itself: the top of the sheet above
  // the bump's centre has risen by the exact displacement a t exp(...).
  const growth::BumpField bump(growth::BumpFieldParams{.a = 1.0, .b = 1.0, .h = 4.0, .x0 = 10.0});
  bool found = false;
  for (VertexId v : start.vertices()) {
    const Vec3 p0 = start.position(v);
    if (p0.x() != 10.0 || p0.y() != 5.0) continue;
    found = true;
    CHECK(sim.tissue().position(v).y() == Approx(5.0 + bump.displacement(10.0, 0.0, 2.0)).epsilon(1e-4));
  }
  CHECK(found);
}

TEST_CASE("voronoi_growth.yaml runs with every division rule", "[sim][growth][configs]") {
  for (const char* rule : {"main_axis", "shortest_wall", "perpendicular_to_mother_wall", "random", "fixed",
                           "besson_dumais"}) {
    INFO(rule);
    Simulation sim = Simulation::fromFile(sourcePath("configs/voronoi_growth.yaml"),
                                          {std::string("division.rule=") + rule, "time.end=6.0"});
    const std::size_t cells = sim.tissue().numCells();
    const double area = totalMeasure(sim.tissue());
    const std::size_t divisions = runValidated(sim);
    CHECK(divisions > 20);
    CHECK(sim.tissue().numCells() == cells + divisions);
    CHECK(totalMeasure(sim.tissue()) == Approx(area * std::exp(2 * 0.1 * 6.0)).epsilon(1e-4));
  }
}

TEST_CASE("the same config and seed give the same run", "[sim][growth][configs]") {
  auto run = [] {
    Simulation sim = Simulation::fromFile(sourcePath("configs/voronoi_growth.yaml"),
                                          {"division.rule=random", "time.end=4.0"});
    sim.run();
    return std::vector<Vec3>(sim.tissue().positions().begin(), sim.tissue().positions().end());
  };
  CHECK(run() == run());
}

TEST_CASE("dome_meristem.yaml keeps the sheet on its dome", "[sim][growth][configs]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/dome_meristem.yaml"), {"time.end=3.0"});
  const double area = totalMeasure(sim.tissue());
  // Vertices a division creates lie on the straight edge it cut, below the
  // dome; the next growth step projects them. So every vertex that existed
  // before the last step must be on the surface.
  std::size_t before_last = 0, current = sim.tissue().slots(0);
  sim.onStep([&](const Simulation& s) {
    before_last = current;
    current = s.tissue().slots(0);
  });
  const std::size_t divisions = runValidated(sim);
  CHECK(divisions > 0);
  CHECK(totalMeasure(sim.tissue()) > area);
  // Spherical cap of base radius 5 and height 2.5: sphere of radius 6.25
  // centred 3.75 below the base plane.
  for (VertexId v : sim.tissue().vertices()) {
    const double r = (sim.tissue().position(v) - Vec3(0, 0, -3.75)).norm();
    if (v.index() < before_last) CHECK(r == Approx(6.25).epsilon(1e-12));
    else CHECK(r == Approx(6.25).epsilon(0.02));  // on an edge chord
  }
}

TEST_CASE("box_growth_3d.yaml grows and divides polyhedra", "[sim][growth][configs]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/box_growth_3d.yaml"), {"time.end=3.0"});
  const double volume = totalMeasure(sim.tissue());
  const std::size_t divisions = runValidated(sim);
  CHECK(divisions > 10);
  // A linear field: the volume grows as exp(trace(G) t), trace = 0.45.
  CHECK(totalMeasure(sim.tissue()) == Approx(volume * std::exp(0.45 * 3.0)).epsilon(1e-3));
}

TEST_CASE("from_label_image_3d.yaml: a tissue imported from a 3D label image meshes, grows and divides",
          "[sim][growth][configs]") {
  // The shipped config (simplify 0) and the same at simplify 1. scripts/make_label_image.py labels the voxels
  // of its 18 seeds 2..19 and adds two specks (500, 501), which min_cell_size merges: one cell per seed.
  // The uniform field v = r (x - c) scales the tissue by exp(r t) (a wall's fan centre, the vertex mean, scales
  // with it), so the volume grows by exp(3 r t); divisions conserve it. Every cell starts above v_min and
  // passes the threshold (900 +- 45) before the end, so each of the 18 divides at least once.
  const double rate = 0.1, end = 4.0;
  for (const std::string simplify : {"0", "1"}) {
    INFO("simplify " << simplify);
    Simulation sim = Simulation::fromFile(sourcePath("configs/from_label_image_3d.yaml"),
                                          {"tissue.import.simplify=" + simplify});
    const Tissue& t = sim.tissue();
    REQUIRE(t.numCells() == 18);
    const auto& label = t.cellProperties().get<std::int64_t>("label");
    std::set<std::int64_t> labels;
    for (CellId c : t.cells()) labels.insert(label[c]);
    CHECK(*labels.begin() == 2);
    CHECK(*labels.rbegin() == 19);
    double v_min = 1e300;
    for (CellId c : t.cells()) v_min = std::min(v_min, cellMeasure(t, c));
    REQUIRE(v_min * std::exp(3 * rate * end) > 900 + 6 * 45);
    mesh::MeshOptions mo;
    mo.radius_edge_ratio = 2.0;  // proven to terminate; quick
    mo.min_angle_degrees = 0;
    CHECK(mesh::meshTissue(t, mo).numElements() > 18);
    // Each step grows the volume by exp(3 r dt) (the integrator's error aside); a step that also divides cells
    // changes it a little more (a cut through a non-planar wall re-fans its two halves).
    double before = totalMeasure(t), worst_growth = 0, worst_division = 0;
    std::size_t cells_before = t.numCells();
    sim.onStep([&](const Simulation& s) {
      const double ratio = totalMeasure(s.tissue()) / before / std::exp(3 * rate * 0.1) - 1;
      double& worst = s.tissue().numCells() == cells_before ? worst_growth : worst_division;
      worst = std::max(worst, std::abs(ratio));
      before = totalMeasure(s.tissue()), cells_before = s.tissue().numCells();
    });
    const std::size_t divisions = runValidated(sim);
    WARN("simplify " << simplify << ": volume per step off exp(3 r dt) by at most " << worst_growth
                     << " without division, " << worst_division << " with");
    CHECK(divisions >= 18);
    CHECK(sim.tissue().numCells() == 18 + divisions);
    CHECK(worst_growth < 1e-5);
    CHECK(worst_division < 2e-3);  // losing a cell would be 2e-2
    CHECK(mesh::meshTissue(sim.tissue(), mo).numElements() > static_cast<int>(18 + divisions));
  }
}

TEST_CASE("growth and division config errors name their key", "[sim][growth][configs]") {
  const std::string grid = "tissue: {generator: rectangular_grid}\n";
  SECTION("a bad expression") {
    try {
      Simulation::fromYaml(grid + "growth:\n  field: expression\n  expression:\n    vy: \"2*/y\"\n");
      FAIL("no error");
    } catch (const ConfigError& e) {
      CHECK(e.keyPath() == "growth.expression.vy");
      CHECK_THAT(e.what(), Contains("2*/y") && Contains("position"));
    }
  }
  SECTION("bad expression parameters") {
    CHECK_THROWS_WITH(Simulation::fromYaml(grid + "growth:\n  field: expression\n  expression:\n"
                                                  "    vx: r*x\n    parameters: \"r=abc\"\n"),
                      Contains("growth.expression.parameters") && Contains("r=abc"));
  }
  SECTION("a dome projection without a dome") {
    CHECK_THROWS_WITH(Simulation::fromYaml(grid + "growth:\n  field: uniform\n  surface: dome\n"),
                      Contains("growth.surface") && Contains("dome"));
  }
  SECTION("an unknown rule") {
    CHECK_THROWS_WITH(Simulation::fromYaml(grid + "division:\n  rule: errera\n"),
                      Contains("division.rule") && Contains("shortest_wall"));
  }
  SECTION("a zero fixed normal") {
    CHECK_THROWS_WITH(Simulation::fromYaml(grid + "division:\n  rule: fixed\n  fixed_normal: [0, 0, 0]\n"),
                      Contains("division.fixed_normal"));
  }
  SECTION("a zero meristem axis (refused by the field itself)") {
    try {
      Simulation::fromYaml(grid + "growth:\n  field: meristem\n  meristem:\n    axis: [0, 0, 0]\n");
      FAIL("no error");
    } catch (const ConfigError& e) {
      CHECK(e.keyPath() == "growth.meristem.axis");
    }
  }
  SECTION("an expression parameter named like a variable") {
    try {
      Simulation::fromYaml(grid + "growth:\n  field: expression\n  expression:\n    parameters: \"x=1\"\n");
      FAIL("no error");
    } catch (const ConfigError& e) {
      CHECK(e.keyPath() == "growth.expression.parameters");
      CHECK_THAT(e.what(), Contains("reserved"));
    }
  }
  SECTION("a negative bump width") {
    CHECK_THROWS_WITH(Simulation::fromYaml(grid + "growth:\n  field: bump\n  bump:\n    h: -1\n"),
                      Contains("growth.bump.h"));
  }
}

TEST_CASE("a step that inverts a cell names the stage, the cell and the time", "[sim][growth][configs]") {
  Simulation sim = Simulation::fromYaml(
      "tissue: {generator: rectangular_grid}\n"
      "growth:\n  field: anisotropic\n  scheme: euler\n  anisotropic:\n    rates: [-3.0, 0.0, 0.0]\n"
      "time: {end: 2.0, dt: 1.0}\n");
  CHECK_THROWS_WITH(sim.step(), Contains("growth") && Contains("lineage id") && Contains("t = 0"));
}
