// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include "tessella/sim/sections/time_section.hpp"

using tessella::sim::TimeSpan;

TEST_CASE("a span that is a multiple of dt has (end - start) / dt steps", "[sim][time]") {
  CHECK(TimeSpan{0, 10, 1}.numSteps() == 10);
  CHECK(TimeSpan{0, 1, 0.1}.numSteps() == 10);  // 1/0.1 is 10.000000000000002 in binary: no sliver step
  CHECK(TimeSpan{2, 3, 0.25}.numSteps() == 4);
  CHECK(TimeSpan{0, 0, 1}.numSteps() == 0);
}

TEST_CASE("otherwise the last step is shortened to land on end", "[sim][time]") {
  const TimeSpan t{0, 1, 0.3};
  REQUIRE(t.numSteps() == 4);
  CHECK(t.timeAt(0) == 0.0);
  CHECK(t.timeAt(1) == Approx(0.3));
  CHECK(t.timeAt(3) == Approx(0.9));
  CHECK(t.timeAt(4) == 1.0);  // exactly end
  CHECK(t.timeAt(99) == 1.0);
}

TEST_CASE("step times are computed, not accumulated", "[sim][time]") {
  const TimeSpan t{0, 1000, 0.1};
  REQUIRE(t.numSteps() == 10000);
  for (std::size_t k : {1u, 77u, 5000u, 9999u}) CHECK(t.timeAt(k) == static_cast<double>(k) * 0.1);
}
