// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The geometry a Simulation shares between its stages and outputs
// (StepContext::geometry, Simulation::geometry()): a grow-and-divide step
// computes each quantity once, and the outputs compute only what the step's
// divisions made stale.

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>

#include "tessella/sim/run/series_output.hpp"
#include "tessella/sim/run/statistics_output.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/growth_stages.hpp"
#include "tessella/tissue/geometry.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::sourcePath;

namespace {

using Q = GeometryQuantity;

std::size_t divisionsSoFar(const Simulation& sim) {
  for (std::size_t i = 0; i < sim.numStages(); ++i)
    if (const auto* d = dynamic_cast<const DivisionStage*>(&sim.stage(i))) return d->divisions();
  return 0;
}

struct Case {
  const char* config;
  int steps;
};

}  // namespace

TEST_CASE("one grow-and-divide step computes each geometry quantity once", "[sim][geometry]") {
  for (const Case& c : {Case{"configs/voronoi_growth.yaml", 35}, Case{"configs/box_growth_3d.yaml", 20}}) {
    INFO(c.config);
    Simulation sim = Simulation::fromFile(sourcePath(c.config));
    REQUIRE(sim.numStages() == 2);
    REQUIRE(sim.stage(0).name() == "growth");
    REQUIRE(sim.stage(1).name() == "division");
    const bool volumes = sim.tissue().dim() == 3;
    const GeometryCache& g = sim.geometry();
    for (int step = 1; step <= c.steps; ++step) {
      sim.step();
      // The growth stage computes the cell measures of the moved tissue; the
      // division stage reads them without computing anything.
      const auto n = static_cast<std::uint64_t>(step);
      CHECK(g.computations(Q::FaceMeasures) == n);
      CHECK(g.computations(Q::VolumeMeasures) == (volumes ? n : 0));
      CHECK(g.computations(Q::EdgeLengths) == 0);
      CHECK(g.computations(Q::FaceSecondMoments) == 0);
      CHECK(g.computations(Q::VolumeSecondMoments) == 0);
    }
    CHECK(divisionsSoFar(sim) > 0);  // the steps did divide
  }
}

TEST_CASE("snapshots and statistics read the run's geometry: a state is measured once", "[sim][geometry]") {
  const test::ScratchDir dir;
  Simulation sim = Simulation::fromFile(sourcePath("configs/voronoi_growth.yaml"));
  const GeometryCache& g = sim.geometry();
  OutputSpec spec;
  spec.every = 1;
  attachSeriesOutput(sim, dir.path().string(), spec);
  attachStatisticsOutput(sim, dir.path().string(), {}, 1);
  // The initial state: measured once for the snapshot and the statistics row.
  CHECK(g.computations(Q::FaceMeasures) == 1);
  std::uint64_t expected = 1;
  std::size_t divisions = 0;
  for (int step = 1; step <= 35; ++step) {
    sim.step();
    // The moved tissue (growth, read by division), then, if cells divided,
    // the divided one (read by the snapshot and the statistics).
    const std::size_t now = divisionsSoFar(sim);
    expected += 1 + (now > divisions ? 1 : 0);
    divisions = now;
    CHECK(g.computations(Q::FaceMeasures) == expected);
  }
  CHECK(divisions > 0);
  CHECK(g.fresh(sim.tissue(), kCellMeasures));
}
