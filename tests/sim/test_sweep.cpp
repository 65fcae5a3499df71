// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Sweep planning: parsing --vary, the runs and seeds of a plan, refusals.
#include <catch2/catch.hpp>

#include "tessella/sim/config/config_error.hpp"
#include "tessella/sim/run/sweep.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using namespace tessella::sim;

TEST_CASE("--vary splits values at top-level commas only", "[sweep]") {
  const SweepAxis a = parseSweepAxis("growth.uniform.center=[0, 0, 0],[1,0,0], [2,0,0]");
  CHECK(a.key == "growth.uniform.center");
  CHECK(a.values == std::vector<std::string>{"[0, 0, 0]", "[1,0,0]", "[2,0,0]"});
  CHECK(parseSweepAxis("division.size=2").values == std::vector<std::string>{"2"});
  CHECK_THROWS_WITH(parseSweepAxis("division.size"), Catch::Contains("--vary 'division.size': no '='"));
  CHECK_THROWS_WITH(parseSweepAxis("=1,2"), Catch::Contains("no key"));
  CHECK_THROWS_WITH(parseSweepAxis("a=1,,2"), Catch::Contains("an empty value"));
  CHECK_THROWS_WITH(parseSweepAxis("a=[1,2"), Catch::Contains("unbalanced"));
  CHECK_THROWS_WITH(parseSweepAxis("a=1,2,1"), Catch::Contains("'1' is given twice"));
}

TEST_CASE("a sweep plans every combination times every replicate, last axis fastest", "[sweep]") {
  const SweepPlan p = planSweep("configs/voronoi_growth.yaml", {"time.end=1"},
                                {parseSweepAxis("division.mean=1.5,2,2.5"), parseSweepAxis("growth.uniform.rate=0.05,0.1")},
                                2);
  REQUIRE(p.runs.size() == 12);
  CHECK(p.runs[0].values == std::vector<std::string>{"1.5", "0.05"});
  CHECK(p.runs[2].values == std::vector<std::string>{"1.5", "0.1"});
  CHECK(p.runs[11].values == std::vector<std::string>{"2.5", "0.1"});
  CHECK(p.runs[11].name == "run_0011");
  // Seeds: the config's rng_seed (5) plus the replicate, the same for every combination.
  for (const SweepRun& r : p.runs) CHECK(r.rng_seed == 5 + r.replicate);
  CHECK(p.run_configs[11].find("mean: 2.5") != std::string::npos);
  CHECK(p.run_configs[11].find("rng_seed: 6") != std::string::npos);
  CHECK(p.run_configs[11].find("end: 1") != std::string::npos);
}

TEST_CASE("a sweep refuses bad values, repeated and inactive keys before writing anything", "[sweep]") {
  CHECK_THROWS_AS(planSweep("configs/voronoi_growth.yaml", {}, {parseSweepAxis("division.mean=0,1")}, 1), ConfigError);
  CHECK_THROWS_WITH(planSweep("configs/voronoi_growth.yaml", {}, {parseSweepAxis("division.sise=1,2")}, 1),
                    Catch::Contains("division.sise"));
  CHECK_THROWS_WITH(
      planSweep("configs/voronoi_growth.yaml", {}, {parseSweepAxis("division.mean=1"), parseSweepAxis("division.mean=2")}, 1),
      Catch::Contains("given twice"));
  CHECK_THROWS_WITH(planSweep("configs/hex_grid_2d.yaml", {}, {parseSweepAxis("division.size=1,2")}, 1),
                    Catch::Contains("ignores this key"));
  CHECK_THROWS_WITH(planSweep("configs/voronoi_growth.yaml", {}, {parseSweepAxis("division.mean=1")}, 0),
                    Catch::Contains("--replicates must be >= 1"));
}
