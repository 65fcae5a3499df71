// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Thousands of random divisions in 2D, on a curved sheet and in 3D: the
// complex must stay valid, measures conserved, policies applied, lineage
// ids unique.

#include <catch2/catch.hpp>

#include <random>
#include <unordered_set>

#include "fixtures.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;

namespace {

struct Stats {
  int divisions = 0;
  int refused = 0;
};

// Divides random cells by random planes through their centroids.
// validate_every = 1 checks after every division.
Stats randomDivisions(Tissue& t, int target, int validate_every, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> unit(-0.2, 0.2);
  auto& amount = t.cellProperties().add<double>("amount", 1.0, DivisionPolicy::SplitByMeasure);
  auto& kind = t.cellProperties().add<int>("kind", 0, DivisionPolicy::Copy);
  for (CellId c : t.cells()) kind[c] = static_cast<int>(c.index() % 3);
  double amount_total = 0;
  for (CellId c : t.cells()) amount_total += amount[c];
  const double measure_total = totalMeasure(t);
  std::unordered_set<std::int64_t> seen;
  for (CellId c : t.cells()) seen.insert(t.lineageId(c));
  Stats s;
  while (s.divisions < target) {
    const CellId c(static_cast<Index>(rng() % t.cellSlots()));
    Vec3 n(gauss(rng), gauss(rng), t.dim() == 3 || t.embedding() == Embedding::Surface ? gauss(rng) : 0.0);
    const Vec3 g = cellCentroid(t, c);
    const double size = std::pow(cellMeasure(t, c), 1.0 / t.dim());
    const Vec3 offset = size * Vec3(unit(rng), unit(rng), t.dim() == 3 ? unit(rng) : 0.0);
    const int kind_before = kind[c];
    const std::int64_t lineage_before = t.lineageId(c);
    try {
      const CellSplit split = t.splitCell(c, Plane{g + offset, n});
      ++s.divisions;
      REQUIRE(kind[split.daughter] == kind_before);
      REQUIRE(t.parentId(split.daughter) == lineage_before);
      REQUIRE(seen.insert(t.lineageId(c)).second);
      REQUIRE(seen.insert(t.lineageId(split.daughter)).second);
    } catch (const GeometryError&) {
      ++s.refused;  // slivers and planes missing a non-convex cell: refused, nothing changed
    }
    if (s.divisions % validate_every == 0 || s.divisions == target) {
      const ValidationReport r = validate(t);
      INFO("after " << s.divisions << " divisions: " << r.message);
      REQUIRE(r.ok);
    }
  }
  double amount_after = 0;
  for (CellId c : t.cells()) amount_after += amount[c];
  CHECK(amount_after == Approx(amount_total).epsilon(1e-12));
  CHECK(totalMeasure(t) == Approx(measure_total).epsilon(1e-12));
  CHECK(t.numCells() == seen.size() - 2 * static_cast<std::size_t>(s.divisions) + s.divisions);
  return s;
}

}  // namespace

TEST_CASE("thousands of random 2D divisions keep the complex valid", "[tissue][editing][random]") {
  Tissue t = hexagonalGrid(4, 4);
  const Stats s = randomDivisions(t, 3000, 100, 42);
  CHECK(t.numCells() == 16 + 3000);
  CHECK(s.refused < s.divisions / 10);
}

TEST_CASE("random divisions on a curved sheet", "[tissue][editing][random]") {
  Tissue t = fixtures::curvedSheet(4, 4, 1.0, 1.5);
  randomDivisions(t, 1000, 50, 7);
  CHECK(t.numCells() == 16 + 1000);
}

TEST_CASE("thousands of random 3D divisions keep the complex valid", "[tissue][editing][random]") {
  Tissue t = boxGrid(2, 2, 2);
  const Stats s = randomDivisions(t, 2000, 100, 99);
  CHECK(t.numCells() == 8 + 2000);
  CHECK(s.refused < s.divisions / 10);
}

TEST_CASE("random divisions validated after every single one", "[tissue][editing][random][slow]") {
  Tissue t2 = hexagonalGrid(3, 3);
  randomDivisions(t2, 3000, 1, 1);
  Tissue t3 = boxGrid(2, 2, 2);
  randomDivisions(t3, 2000, 1, 2);
}
