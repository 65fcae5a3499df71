// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "tessella/sim/simulation.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::sim;
using Catch::Matchers::Contains;

namespace {

// Homogeneous growth about the origin: every length grows by (1 + rate dt)
// per step, so a 2D area grows by (1 + rate dt)^2.
class UniformExpansion : public Stage {
 public:
  explicit UniformExpansion(double rate) : rate_(rate) {}
  std::string name() const override { return "uniform expansion"; }
  void apply(Tissue& tissue, const StepContext& context) override {
    for (Vec3& p : tissue.mutablePositions()) p *= 1.0 + rate_ * context.dt;
  }

 private:
  double rate_;
};

class FailsAtTime : public Stage {
 public:
  explicit FailsAtTime(double t) : t_(t) {}
  std::string name() const override { return "fragile"; }
  void apply(Tissue&, const StepContext& context) override {
    if (context.time >= t_) throw GeometryError("cell 3 inverted");
  }

 private:
  double t_;
};

}  // namespace

TEST_CASE("stages run every step and the clock follows the time span", "[sim][simulation]") {
  Simulation sim(rectangularGrid(2, 2), SimulationOptions{TimeSpan{0, 1, 0.25}, 1});
  sim.addStage(std::make_unique<UniformExpansion>(0.4));
  std::vector<double> seen;
  sim.onStep([&](const Simulation& s) {
    seen.push_back(s.time());
    CHECK(s.tissue().time() == s.time());
  });
  CHECK(sim.numSteps() == 4);
  CHECK(sim.tissue().time() == 0.0);
  sim.run();
  CHECK(sim.finished());
  CHECK(sim.stepsDone() == 4);
  CHECK(seen == std::vector<double>{0.25, 0.5, 0.75, 1.0});
  CHECK(totalMeasure(sim.tissue()) == Approx(4.0 * std::pow(1.1, 8)));
  CHECK_THROWS_AS(sim.step(), std::logic_error);
}

TEST_CASE("the shortened last step has the remaining length", "[sim][simulation]") {
  Simulation sim(rectangularGrid(1, 1), SimulationOptions{TimeSpan{0, 1, 0.4}, 1});
  sim.addStage(std::make_unique<UniformExpansion>(1.0));
  sim.run();
  REQUIRE(sim.stepsDone() == 3);
  // Steps of 0.4, 0.4 and 0.2: side 1.4 * 1.4 * 1.2.
  CHECK(totalMeasure(sim.tissue()) == Approx(std::pow(1.4 * 1.4 * 1.2, 2)));
}

TEST_CASE("runUntil stops at the requested time or at the end", "[sim][simulation]") {
  Simulation sim(hexagonalGrid(2, 2), SimulationOptions{TimeSpan{1, 3, 0.5}, 1});
  sim.runUntil(2.0);
  CHECK(sim.stepsDone() == 2);
  CHECK(sim.time() == 2.0);
  sim.runUntil(2.0);  // already there
  CHECK(sim.stepsDone() == 2);
  sim.runUntil(100.0);
  CHECK(sim.finished());
  CHECK(sim.time() == 3.0);
}

TEST_CASE("a failing stage is reported with its name, step and time", "[sim][simulation]") {
  Simulation sim(rectangularGrid(2, 1), SimulationOptions{TimeSpan{0, 5, 1}, 1});
  sim.addStage(std::make_unique<FailsAtTime>(2.0));
  sim.runUntil(2.0);
  try {
    sim.step();
    FAIL("expected a SimulationError");
  } catch (const SimulationError& e) {
    CHECK_THAT(e.what(), Contains("step 3") && Contains("t = 2.0") && Contains("'fragile'") &&
                             Contains("cell 3 inverted"));
  }
}

TEST_CASE("the stage random stream is reproducible from the seed", "[sim][simulation]") {
  Simulation a(rectangularGrid(1, 1), SimulationOptions{TimeSpan{}, 42});
  Simulation b(rectangularGrid(1, 1), SimulationOptions{TimeSpan{}, 42});
  Simulation c(rectangularGrid(1, 1), SimulationOptions{TimeSpan{}, 43});
  const auto x = a.rng()();
  CHECK(x == b.rng()());
  CHECK(x != c.rng()());
}

TEST_CASE("a Simulation rejects a bad time span from code", "[sim][simulation]") {
  CHECK_THROWS_AS(Simulation(rectangularGrid(1, 1), SimulationOptions{TimeSpan{0, 1, 0}, 1}), InputError);
  CHECK_THROWS_AS(Simulation(rectangularGrid(1, 1), SimulationOptions{TimeSpan{2, 1, 1}, 1}), InputError);
}

TEST_CASE("a Simulation from YAML builds the generator's tissue", "[sim][simulation]") {
  Simulation sim = Simulation::fromYaml(
      "tissue:\n  generator: hexagonal_grid\n  hexagonal_grid: {nx: 3, ny: 4, radius: 2}\n"
      "time: {start: 1, end: 2, dt: 0.5}\nrng_seed: 5\n");
  CHECK(sim.tissue().numCells() == 12);
  CHECK(totalMeasure(sim.tissue()) == Approx(12 * 1.5 * std::sqrt(3.0) * 4));
  CHECK(sim.time() == 1.0);
  CHECK(sim.numSteps() == 2);
  CHECK(sim.options().rng_seed == 5);
  CHECK(sim.numStages() == 0);  // the config turns on no growth, division or solver section
}
