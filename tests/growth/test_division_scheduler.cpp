// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <omp.h>

#include <cmath>
#include <set>

#include "growth_fixtures.hpp"
#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/division_walls.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::growth;
using Catch::Matchers::Contains;

TEST_CASE("every cell over a fixed threshold divides once", "[growth][scheduler]") {
  Tissue t = rectangularGrid(4, 4, 1.0, 0.5);  // cells of area 0.5, long along x
  t.setTime(3.0);
  DivisionScheduler s(SizeThreshold::fixed(0.4), makeDivisionRule("main_axis"));
  GeometryCache g;
  const DivisionReport r = s.step(t, g);
  CHECK(r.divided.size() == 16);
  CHECK(r.skipped.empty());
  CHECK(t.numCells() == 32);
  REQUIRE(validate(t).ok);
  const auto& tags = t.wallProperties().get<std::int64_t>(kDivisionWallProperty);
  std::set<std::int64_t> lineages;
  for (const DivisionRecord& d : r.divided) {
    CHECK(t.parentId(d.cell) == d.mother_lineage);
    CHECK(t.parentId(d.daughter) == d.mother_lineage);
    CHECK(t.birthTime(d.daughter) == 3.0);
    CHECK(tags[d.wall] == d.mother_lineage);
    CHECK(wallMeasure(t, d.wall) == Approx(0.5));  // across the long side
    CHECK(birthWalls(t, d.daughter) == std::vector<WallId>{d.wall});
  }
  for (CellId c : t.cells()) lineages.insert(t.lineageId(c));
  CHECK(lineages.size() == 32);
  // The daughters (area 0.25) are below threshold: nothing more happens.
  CHECK(s.step(t, g).divided.empty());
}

TEST_CASE("a per-cell threshold property selects the cells", "[growth][scheduler]") {
  Tissue t = rectangularGrid(3, 1);
  auto& thr = t.cellProperties().add<double>("my_threshold", 10.0);
  thr[CellId(1)] = 0.5;
  DivisionScheduler s(SizeThreshold::fromProperty("my_threshold"), makeDivisionRule("shortest_wall"));
  GeometryCache g;
  const DivisionReport r = s.step(t, g);
  REQUIRE(r.divided.size() == 1);
  CHECK(r.divided[0].cell == CellId(1));

  DivisionScheduler missing(SizeThreshold::fromProperty("nope"), makeDivisionRule("main_axis"));
  CHECK_THROWS_WITH(missing.step(t, g), Contains("'nope'"));
}

TEST_CASE("noisy thresholds are drawn at birth and redrawn by daughters", "[growth][scheduler]") {
  Tissue t = rectangularGrid(40, 40);
  const double mean = 1.5, sd = 0.1;
  DivisionScheduler s(SizeThreshold::noisy(mean, sd), makeDivisionRule("main_axis"),
                      DivisionOptions{.seed = 11});
  GeometryCache g;
  CHECK(s.step(t, g).divided.empty());  // every cell has area 1 = mean - 5 sd
  const auto& thr = t.cellProperties().get<double>("division_threshold");
  REQUIRE(t.numCells() == 1600);
  double m = 0, m2 = 0;
  for (CellId c : t.cells()) {
    m += thr[c] / 1600;
    m2 += thr[c] * thr[c] / 1600;
  }
  CHECK(m == Approx(mean).margin(4 * sd / 40));
  CHECK(std::sqrt(m2 - m * m) == Approx(sd).margin(0.01));  // sampling sd of the sd ~ 0.0018

  // Give one cell a low threshold: its daughters draw fresh values.
  t.cellProperties().get<double>("division_threshold")[CellId(0)] = 0.5;
  const DivisionReport r = s.step(t, g);
  REQUIRE(r.divided.size() == 1);
  const auto& after = t.cellProperties().get<double>("division_threshold");
  CHECK(after[r.divided[0].cell] != 0.5);
  CHECK(after[r.divided[0].daughter] != after[r.divided[0].cell]);
  CHECK(after[r.divided[0].daughter] > 0);

  CHECK_THROWS_AS(SizeThreshold::noisy(-1, 0.1), InputError);
  CHECK_THROWS_AS(SizeThreshold::fixed(0.0), InputError);
}

namespace {
// A rule whose plane runs along the cell's left wall: splitCell must refuse it.
class AlongWallRule final : public DivisionRule {
 public:
  Plane plane(const Tissue& t, CellId c, Rng&) const override {
    return Plane{t.position(t.cellVertices(c).front()), Vec3::UnitX()};
  }
  std::string name() const override { return "along_wall"; }
};
}  // namespace

TEST_CASE("degenerate cuts are retried perturbed, then skipped and reported", "[growth][scheduler]") {
  GeometryCache g;
  SECTION("retry succeeds") {
    Tissue t = testing::rectangleCell(1.0, 1.0);
    DivisionScheduler s(SizeThreshold::fixed(0.5), std::make_shared<AlongWallRule>());
    const DivisionReport r = s.step(t, g);
    REQUIRE(r.divided.size() == 1);
    CHECK(r.divided[0].attempts > 1);
    CHECK(validate(t).ok);
  }
  SECTION("one attempt only: skipped and reported") {
    Tissue t = testing::rectangleCell(1.0, 1.0);
    DivisionScheduler s(SizeThreshold::fixed(0.5), std::make_shared<AlongWallRule>(),
                        DivisionOptions{.max_attempts = 1});
    const DivisionReport r = s.step(t, g);
    CHECK(r.divided.empty());
    REQUIRE(r.skipped.size() == 1);
    CHECK(r.skipped[0].lineage == t.lineageId(CellId(0)));
    CHECK_THAT(r.skipped[0].reason, Contains("along_wall"));
    CHECK(t.numCells() == 1);
    CHECK(validate(t).ok);
  }
}

TEST_CASE("a division gate lets only the cells it accepts divide", "[growth][scheduler]") {
  Tissue t = rectangularGrid(4, 1);  // four unit cells, all over the threshold
  DivisionOptions options;
  // Divide only the cells left of x = 2 (a stand-in for a field above a value).
  options.gate = [](const Tissue& tissue, CellId c) { return cellCentroid(tissue, c).x() < 2.0; };
  DivisionScheduler s(SizeThreshold::fixed(0.5), makeDivisionRule("main_axis"), options);
  GeometryCache g;
  const DivisionReport r = s.step(t, g);
  REQUIRE(r.divided.size() == 2);
  CHECK(r.skipped.empty());  // gated cells are not "skipped": they were never tried
  for (const DivisionRecord& d : r.divided) CHECK(cellCentroid(t, d.cell).x() < 2.0);
  CHECK(t.numCells() == 6);
  REQUIRE(validate(t).ok);
}

namespace {
// Two steps on 6400 cells (enough for every parallel loop of a 2D step): all
// divide by the main axis (planes in parallel), then the squares they make by
// the random rule (planes drawn one after the other).
struct TwoSteps {
  Tissue tissue;
  std::vector<DivisionReport> reports;
};
TwoSteps twoSteps(int threads) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  TwoSteps out{rectangularGrid(80, 80, 1.0, 0.5), {}};
  GeometryCache g;
  DivisionScheduler first(SizeThreshold::fixed(0.4), makeDivisionRule("main_axis"));
  out.reports.push_back(first.step(out.tissue, g));
  DivisionScheduler second(SizeThreshold::fixed(0.2), makeDivisionRule("random"), DivisionOptions{.seed = 3});
  out.reports.push_back(second.step(out.tissue, g));
  omp_set_num_threads(saved);
  return out;
}
}  // namespace

TEST_CASE("a 2D division step is the same with one and two threads", "[growth][scheduler]") {
  const TwoSteps one = twoSteps(1), two = twoSteps(2);
  REQUIRE(one.reports[0].divided.size() == 6400);
  REQUIRE(one.reports[1].divided.size() == 12800);
  REQUIRE(one.tissue.topology().layout() == two.tissue.topology().layout());
  CHECK(std::vector<Vec3>(one.tissue.positions().begin(), one.tissue.positions().end()) ==
        std::vector<Vec3>(two.tissue.positions().begin(), two.tissue.positions().end()));
  for (const char* name : {Tissue::kLineageName, Tissue::kParentName})
    CHECK(one.tissue.cellProperties().get<std::int64_t>(name).values() ==
          two.tissue.cellProperties().get<std::int64_t>(name).values());
  CHECK(one.tissue.wallProperties().get<std::int64_t>(kDivisionWallProperty).values() ==
        two.tissue.wallProperties().get<std::int64_t>(kDivisionWallProperty).values());
  for (std::size_t s = 0; s < 2; ++s) {
    REQUIRE(one.reports[s].divided.size() == two.reports[s].divided.size());
    for (std::size_t i = 0; i < one.reports[s].divided.size(); ++i) {
      const DivisionRecord &a = one.reports[s].divided[i], &b = two.reports[s].divided[i];
      CHECK((a.cell == b.cell && a.daughter == b.daughter && a.wall == b.wall && a.attempts == b.attempts));
    }
  }
  REQUIRE(validate(one.tissue).ok);
  CHECK(one.tissue.numCells() == 25600);
}
