// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include "tessella/sim/run/progress_meter.hpp"

using namespace tessella::sim;
using namespace std::chrono_literals;
using Catch::Matchers::Contains;

TEST_CASE("progress lines are rate limited, the last one always comes", "[sim][progress]") {
  const auto t0 = ProgressMeter::Clock::time_point{};
  ProgressMeter meter(100, 1000ms, t0);
  CHECK_FALSE(meter.update(1, 0.1, 10, t0 + 200ms));  // a short run stays quiet
  const auto first = meter.update(10, 1.0, 12, t0 + 1000ms);
  REQUIRE(first);
  CHECK_THAT(*first, Contains("step 10/100 (10%)") && Contains("t = 1") && Contains("cells 12"));
  // 10 steps took 1 s, 90 remain: ETA 9 s.
  CHECK_THAT(*first, Contains("elapsed 1.0 s") && Contains("ETA 9.0 s"));
  CHECK_FALSE(meter.update(11, 1.1, 12, t0 + 1500ms));
  CHECK(meter.update(20, 2.0, 14, t0 + 2000ms));
  const auto last = meter.update(100, 10.0, 30, t0 + 2100ms);
  REQUIRE(last);
  CHECK_THAT(*last, Contains("step 100/100 (100%)"));
  CHECK_THAT(*last, !Contains("ETA"));
}

TEST_CASE("durations read naturally", "[sim][progress]") {
  CHECK(formatDuration(0.25s) == "250 ms");
  CHECK(formatDuration(2.14s) == "2.1 s");
  CHECK(formatDuration(185s) == "3 min 05 s");
  CHECK(formatDuration(3720s) == "1 h 02 min");
}
