// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Walls files (wall_vtu.hpp): one VTK cell per live wall over the live
// vertices, arrays per wall read back exactly (scalars, vectors, symmetric
// tensors; from wall properties), the series of walls files beside a tissue
// series (<name>.<tag>.pvd) cut when a run resumes, and the errors.
#include <catch2/catch.hpp>

#include "io_test_support.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/io/pvd.hpp"
#include "tessella/io/series.hpp"
#include "tessella/io/wall_vtu.hpp"

#include <filesystem>

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

TEST_CASE("A walls file holds symmetric tensors and the walls' property columns", "[io][walls]") {
  TempDir dir;
  const bool three = GENERATE(false, true);
  Tissue t = three ? boxGrid(2, 1, 1) : rectangularGrid(2, 2);
  PropertyStore& walls = t.wallProperties();
  auto& scalar = walls.add<double>("rest", 0.0, DivisionPolicy::Copy);
  auto& vector = walls.add<Vec3>("fibre", Vec3::Zero(), DivisionPolicy::Copy);
  auto& tensor = walls.add<Sym3>("stress", Sym3{}, DivisionPolicy::Copy);
  walls.add<int>("count", 0, DivisionPolicy::Copy);
  for (WallId w : t.walls()) {
    const double k = w.index();
    scalar[w] = k / 3.0;
    vector[w] = Vec3(1.0, k, -k / 7.0);
    tensor[w] = Sym3{{k, 2 * k, 3 * k, 0.1 * k, 0.2 * k, 0.3 * k}};  // xx yy zz xy xz yz: all different
  }
  const io::WallArrays a = io::wallPropertyArrays(t, {"rest", "fibre", "stress", "absent"});
  CHECK(a.scalars.size() == 1);
  CHECK(a.vectors.size() == 1);
  CHECK(a.tensors.size() == 1);
  CHECK_THROWS_WITH(io::wallPropertyArrays(t, {"count"}), Catch::Contains("'count'"));
  io::writeWallsVtu(t, dir.file("t.walls.vtu"), a);
  const io::WallsFile f = io::readWallsVtu(dir.file("t.walls.vtu"));
  std::size_t k = 0;
  for (WallId w : t.walls()) {
    CHECK(f.arrays.scalars.at("rest")[k] == scalar[w]);
    CHECK(f.arrays.vectors.at("fibre")[k] == vector[w]);
    CHECK(f.arrays.tensors.at("stress")[k].v == tensor[w].v);
    ++k;
  }
}

TEST_CASE("Walls files beside a series are listed in a series of their own, cut on resume", "[io][walls][series]") {
  namespace fs = std::filesystem;
  TempDir dir;
  Tissue t = rectangularGrid(2, 2);
  io::WallArrays a;
  a.scalars["value"] = std::vector<double>(t.numWalls(), 1.0);
  {
    io::SeriesWriter writer(dir.path().string(), "tissue");
    writer.setBesideSeries({"walls", "pin"});
    for (int step = 0; step < 4; ++step) {
      // Walls files at every step, PIN files at the even ones, written before their snapshot.
      io::writeWallsVtu(t, io::besideSnapshotPath(writer.nextPath(), "walls"), a);
      if (step % 2 == 0) io::writeWallsVtu(t, io::besideSnapshotPath(writer.nextPath(), "pin"), a);
      writer.write(t, 0.5 * step);
    }
    CHECK(writer.besidePvdPath("walls") == dir.file("tissue.walls.pvd"));
    CHECK_THROWS_AS(writer.setBesideSeries({"a.b"}), InputError);
  }
  const auto walls = io::readPvdFile(dir.file("tissue.walls.pvd"));
  REQUIRE(walls.size() == 4);
  CHECK(walls[3].time == 1.5);
  CHECK(walls[3].file == "tissue_000003.walls.vtu");
  const auto pin = io::readPvdFile(dir.file("tissue.pin.pvd"));
  REQUIRE(pin.size() == 2);
  CHECK(pin[1].time == 1.0);
  CHECK(pin[1].file == "tissue_000002.pin.vtu");
  // Resume after t = 0.5: the later snapshots go with the files beside them, and both series are cut.
  io::SeriesWriter writer(dir.path().string(), "tissue");
  writer.setBesideSeries({"walls", "pin"});
  writer.continueAfter(0.5);
  CHECK(writer.steps() == 2);
  CHECK(io::readPvdFile(dir.file("tissue.walls.pvd")).size() == 2);
  CHECK(io::readPvdFile(dir.file("tissue.pin.pvd")).size() == 1);
  for (const char* gone : {"tissue_000002.vtu", "tissue_000002.walls.vtu", "tissue_000002.pin.vtu",
                           "tissue_000003.walls.vtu"})
    CHECK_FALSE(fs::exists(dir.file(gone)));
  CHECK(fs::exists(dir.file("tissue_000001.walls.vtu")));
  CHECK(fs::exists(dir.file("tissue_000000.pin.vtu")));
  // The next snapshot's walls file joins the cut series.
  io::writeWallsVtu(t, io::besideSnapshotPath(writer.nextPath(), "walls"), a);
  writer.write(t, 0.75);
  const auto after = io::readPvdFile(dir.file("tissue.walls.pvd"));
  REQUIRE(after.size() == 3);
  CHECK(after[2].file == "tissue_000002.walls.vtu");
  CHECK(after[2].time == 0.75);
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
