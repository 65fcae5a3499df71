// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>

#include "tessella/generators/grids.hpp"
#include "tessella/sim/run/tissue_summary.hpp"

using namespace tessella;
using namespace tessella::sim;

TEST_CASE("distributionOf: quartiles by linear interpolation, population CV", "[sim][summary]") {
  const Distribution d = distributionOf({5, 1, 4, 2, 3});
  CHECK(d.count == 5);
  CHECK(d.min == 1);
  CHECK(d.q1 == 2);
  CHECK(d.median == 3);
  CHECK(d.q3 == 4);
  CHECK(d.max == 5);
  CHECK(d.mean == 3);
  CHECK(d.cv == Approx(std::sqrt(2.0) / 3.0));  // population variance of 1..5 is 2

  const Distribution e = distributionOf({1, 2, 3, 4});
  CHECK(e.q1 == Approx(1.75));
  CHECK(e.median == Approx(2.5));
  CHECK(e.q3 == Approx(3.25));

  const Distribution one = distributionOf({7});
  CHECK(one.q1 == 7);
  CHECK(one.cv == 0);
  CHECK_THROWS_AS(distributionOf({}), InputError);
}

TEST_CASE("summary of a hexagonal grid matches the geometry of regular hexagons", "[sim][summary]") {
  const double r = 0.5;
  const Tissue t = hexagonalGrid(4, 3, r);
  const TissueSummary s = summarizeTissue(t);
  const double hex_area = 1.5 * std::sqrt(3.0) * r * r;
  CHECK(s.dim == 2);
  CHECK(s.cells == 12);
  CHECK(s.counts[2] == 12);
  CHECK(s.counts[3] == 0);
  CHECK(s.total_measure == Approx(12 * hex_area));
  CHECK(s.cell_sizes.min == Approx(hex_area));
  CHECK(s.cell_sizes.max == Approx(hex_area));
  CHECK(s.cell_sizes.cv == Approx(0).margin(1e-12));
  CHECK(s.validation.ok);
  // Euler for a disk-like sheet: V - E + F = 1.
  CHECK(static_cast<long>(s.counts[0]) - static_cast<long>(s.counts[1]) + static_cast<long>(s.counts[2]) == 1);
}

TEST_CASE("summary of a box grid counts volumes", "[sim][summary]") {
  const Tissue t = boxGrid(2, 3, 4, 0.5, 1.0, 2.0);
  const TissueSummary s = summarizeTissue(t);
  CHECK(s.dim == 3);
  CHECK(s.cells == 24);
  CHECK(s.counts[3] == 24);
  CHECK(s.counts[0] == 3 * 4 * 5);
  CHECK(s.total_measure == Approx(24 * 1.0));
  CHECK(s.cell_sizes.median == Approx(1.0));
  CHECK(s.validation.ok);
}
