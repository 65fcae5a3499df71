// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Every configs/*.yaml is run to its end, as shipped, with the tissue
// validated after every step: a config added later is covered without a
// test of its own (the per-config tests check what each one is about).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "tessella/sim/simulation.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::sourcePath;

TEST_CASE("every example config runs to its end with a valid tissue at every step", "[sim][configs]") {
  std::vector<std::filesystem::path> configs;
  for (const auto& entry : std::filesystem::directory_iterator(sourcePath("configs")))
    if (entry.path().extension() == ".yaml") configs.push_back(entry.path());
  std::sort(configs.begin(), configs.end());
  REQUIRE(configs.size() >= 9);  // the configs shipped when this test was written
  for (const auto& path : configs) {
    INFO(path.filename().string());
    Simulation sim = Simulation::fromFile(path.string());
    REQUIRE(validate(sim.tissue()).ok);
    REQUIRE(sim.tissue().numCells() > 0);
    std::size_t steps = 0;
    tessella::sim::test::validateEveryStep(sim);
    sim.onStep([&](const Simulation& s) {
      ++steps;
      REQUIRE(std::isfinite(totalMeasure(s.tissue())));
    });
    sim.run();
    CHECK(sim.finished());
    CHECK(steps == sim.numSteps());
  }
}
