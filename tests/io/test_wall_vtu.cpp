// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Walls files (wall_vtu.hpp): one VTK cell per live wall over the live
// vertices, arrays per wall read back exactly, and the errors.
#include <catch2/catch.hpp>

#include "io_test_support.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/io/wall_vtu.hpp"

using namespace tessella;
using tessella::io::testing::TempDir;

TEST_CASE("A walls file holds every live wall with its arrays, 2D and 3D", "[io][walls]") {
  TempDir dir;
  const bool three = GENERATE(false, true);
  Tissue t = three ? boxGrid(2, 2, 1) : rectangularGrid(3, 2);
  io::WallArrays a;
  std::vector<double>& s = a.scalars["value"];
  std::vector<Vec3>& v = a.vectors["direction"];
  for (WallId w : t.walls()) {
    s.push_back(0.1 * w.index() + 1.0 / 3.0);
    v.emplace_back(w.index(), -1.0 / 7.0, 2.0);
  }
  const std::string path = io::besideSnapshotPath(dir.file("tissue_000004.vtu"), "pin");
  CHECK(path == dir.file("tissue_000004.pin.vtu"));
  io::writeWallsVtu(t, path, a);
  const io::WallsFile f = io::readWallsVtu(path);
  CHECK(f.points == t.numVertices());
  REQUIRE(f.wall_id.size() == t.numWalls());
  std::size_t k = 0;
  for (WallId w : t.walls()) {
    CHECK(f.wall_id[k] == static_cast<int>(w.index()));
    CHECK(f.points_per_wall[k] == (three ? 4 : 2));  // a box grid's walls are squares
    ++k;
  }
  CHECK(f.arrays.scalars.at("value") == s);  // exact
  CHECK(f.arrays.vectors.at("direction") == v);
}

TEST_CASE("A walls file refuses arrays of the wrong size or name", "[io][walls][errors]") {
  TempDir dir;
  Tissue t = rectangularGrid(2, 2);
  io::WallArrays a;
  a.scalars["short"] = std::vector<double>(t.numWalls() - 1, 0.0);
  CHECK_THROWS_WITH(io::writeWallsVtu(t, dir.file("w.vtu"), a),
                    Catch::Contains("'short' has " + std::to_string(t.numWalls() - 1) + " values for " +
                                    std::to_string(t.numWalls()) + " walls"));
  a.scalars.clear();
  a.scalars["wall_id"] = std::vector<double>(t.numWalls(), 0.0);
  CHECK_THROWS_WITH(io::writeWallsVtu(t, dir.file("w.vtu"), a), Catch::Contains("reserved"));
  CHECK_THROWS_AS(io::readWallsVtu(dir.file("missing.vtu")), InputError);
}
