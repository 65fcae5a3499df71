// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// What a restart needs from a snapshot besides positions and values: each
// property's division policy and default (a Reset column's default is what
// every later daughter gets), and the run state written beside the tissue.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "io_test_support.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using tessella::io::testing::TempDir;

TEST_CASE("snapshots keep every property's default, and daughters after a restart get it", "[io][restart]") {
  TempDir dir;
  Tissue t = rectangularGrid(2, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  t.cellProperties().add<double>("threshold", nan, DivisionPolicy::Reset);
  t.cellProperties().add<std::int32_t>("kind", 7, DivisionPolicy::Reset);
  t.cellProperties().add<Vec3>("polarity", Vec3(1, 2, 3), DivisionPolicy::Reset);
  t.properties(0).add<float>("stiffness", 2.5f, DivisionPolicy::Copy);
  for (CellId c : t.cells()) t.cellProperties().get<double>("threshold")[c] = 1.5;
  const std::string path = dir.file("t.vtu");
  io::writeTissueVtu(t, path);

  Tissue back = io::readTissueVtu(path);
  const auto& threshold = back.cellProperties().get<double>("threshold");
  CHECK(std::isnan(threshold.defaultValue()));
  CHECK(threshold.policy() == DivisionPolicy::Reset);
  CHECK(back.cellProperties().get<std::int32_t>("kind").defaultValue() == 7);
  CHECK(back.cellProperties().get<Vec3>("polarity").defaultValue() == Vec3(1, 2, 3));
  CHECK(back.properties(0).get<float>("stiffness").defaultValue() == 2.5f);

  const CellId mother = *back.cells().begin();
  const CellSplit split = back.splitCell(mother, Plane{cellCentroid(back, mother), Vec3::UnitX()});
  CHECK(std::isnan(back.cellProperties().get<double>("threshold")[split.daughter]));
  CHECK(std::isnan(back.cellProperties().get<double>("threshold")[mother]));
  CHECK(back.cellProperties().get<std::int32_t>("kind")[split.daughter] == 7);
  CHECK(back.cellProperties().get<Vec3>("polarity")[split.daughter] == Vec3(1, 2, 3));
}

TEST_CASE("the run state written with a snapshot reads back unchanged", "[io][restart]") {
  TempDir dir;
  const Tissue t = hexagonalGrid(2, 2);
  const io::RunState state{{"clock.start", "0.1"}, {"rng.stream", "1 2 3 4"}, {"empty", ""}, {"x.y", "a=b"}};
  const std::string path = dir.file("s.vtu");
  io::writeTissueVtu(t, path, {}, state);
  const io::Snapshot back = io::readSnapshot(path);
  CHECK(back.state == state);
  CHECK(back.tissue.numCells() == t.numCells());

  io::writeTissueVtu(t, dir.file("none.vtu"));
  CHECK(io::readSnapshot(dir.file("none.vtu")).state.empty());

  CHECK_THROWS_AS(io::writeTissueVtu(t, dir.file("bad.vtu"), {}, io::RunState{{"a=b", "1"}}), InputError);
  CHECK_THROWS_AS(io::writeTissueVtu(t, dir.file("bad.vtu"), {}, io::RunState{{"", "1"}}), InputError);
  CHECK_FALSE(std::filesystem::exists(dir.file("bad.vtu")));
}
