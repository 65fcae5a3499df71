// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include "fixtures.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"

using namespace tessella;

TEST_CASE("properties are typed, named columns with a default", "[tissue][properties]") {
  Tissue t = fixtures::threeCells();
  auto& auxin = t.cellProperties().add<double>("auxin", 2.5, DivisionPolicy::SplitByMeasure);
  CHECK(auxin.size() == t.cellSlots());
  for (CellId c : t.cells()) CHECK(auxin[c] == 2.5);
  CHECK(t.cellProperties().has("auxin"));
  CHECK_THROWS_AS(t.cellProperties().add<double>("auxin", 0.0), InputError);
  CHECK_THROWS_AS(t.cellProperties().get<int>("auxin"), InputError);
  CHECK_THROWS_AS(t.cellProperties().get<double>("nope"), InputError);
  CHECK_THROWS_AS(t.cellProperties().add<std::string>("name", "x", DivisionPolicy::SplitByMeasure), InputError);
  CHECK_THROWS_AS(t.cellProperties().add<int>("f", 0, DivisionPolicy::Custom), InputError);
  CHECK_THROWS_AS(t.cellProperties().remove(Tissue::kLineageName), InputError);
  t.cellProperties().remove("auxin");
  CHECK_FALSE(t.cellProperties().has("auxin"));
}

TEST_CASE("division applies every policy with the measure fraction", "[tissue][properties][editing]") {
  // A 2 x 1 rectangle cut at x = 0.5: the mother keeps 1/4, the daughter 3/4.
  Tissue t = rectangularGrid(1, 1, 2.0, 1.0);
  const CellId c(0);
  auto& amount = t.cellProperties().add<double>("amount", 8.0, DivisionPolicy::SplitByMeasure);
  auto& count = t.cellProperties().add<std::int64_t>("count", 7, DivisionPolicy::SplitByMeasure);
  auto& type = t.cellProperties().add<int>("type", 3, DivisionPolicy::Copy);
  auto& age = t.cellProperties().add<double>("age", 0.0, DivisionPolicy::Reset);
  auto& custom = t.cellProperties().add<double>(
      "custom", 1.0, DivisionPolicy::Custom,
      [](const double& m, double& a, double& b, double f) { a = m + f; b = m - f; });
  auto& polarity = t.cellProperties().add<Vec3>("polarity", Vec3(1, 2, 3), DivisionPolicy::SplitByMeasure);
  auto& wall_stiffness = t.wallProperties().add<double>("stiffness", 4.0, DivisionPolicy::Copy);
  auto& wall_amount = t.wallProperties().add<double>("pin", 1.0, DivisionPolicy::SplitByMeasure);
  type[c] = 9;
  age[c] = 5.0;
  const CellSplit s = t.splitCell(c, Plane{Vec3(0.5, 0.5, 0), Vec3(1, 0, 0)});
  const CellId d = s.daughter;
  CHECK(cellMeasure(t, c) == Approx(0.5));
  CHECK(cellMeasure(t, d) == Approx(1.5));
  CHECK(amount[c] == Approx(2.0));
  CHECK(amount[d] == Approx(6.0));
  CHECK(amount[c] + amount[d] == 8.0);  // exact: the part gets mother - kept
  CHECK(count[c] + count[d] == 7);
  CHECK(count[c] == 2);  // round(7/4)
  CHECK(type[c] == 9);
  CHECK(type[d] == 9);
  CHECK(age[c] == 0.0);
  CHECK(age[d] == 0.0);
  CHECK(custom[c] == Approx(1.25));
  CHECK(custom[d] == Approx(0.75));
  CHECK((polarity[c] + polarity[d] - Vec3(1, 2, 3)).norm() < 1e-15);
  // The split walls (bottom and top edges) divide by length fraction; the new wall gets defaults.
  double pin_total = 0;
  for (WallId w : t.walls()) pin_total += wall_amount[w];
  CHECK(pin_total == Approx(5.0));  // 4 original walls, 1 new one with the default
  CHECK(wall_stiffness[s.wall] == 4.0);
  CHECK(wall_amount[s.wall] == 1.0);
}

TEST_CASE("lineage ids are unique, parents and birth times are set", "[tissue][lineage]") {
  Tissue t = fixtures::hexagon();
  const CellId c(0);
  CHECK(t.lineageId(c) == 0);
  CHECK(t.parentId(c) == -1);
  t.setTime(3.5);
  const CellSplit s = t.splitCell(c, Plane{Vec3::Zero(), Vec3(0, 1, 0)});
  CHECK(t.lineageId(c) == 1);
  CHECK(t.lineageId(s.daughter) == 2);
  CHECK(t.parentId(c) == 0);
  CHECK(t.parentId(s.daughter) == 0);
  CHECK(t.birthTime(c) == 3.5);
  CHECK(t.birthTime(s.daughter) == 3.5);
  t.restoreLineage(c, 100, 7, 1.0);
  CHECK(t.nextLineageId() == 101);
  CHECK_THROWS_AS(t.restoreLineage(c, -1, 7, 1.0), InputError);
}
