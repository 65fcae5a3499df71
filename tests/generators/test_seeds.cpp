// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Seeds: reproducible uniform random points (checked against the standard's
// fixed mt19937_64 sequence) and CSV reading with errors naming file and line.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "tessella/tissue/errors.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;

namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("tessella_test_seeds_" + name);
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace

TEST_CASE("random seeds follow the documented mt19937_64 mapping", "[seeds]") {
  // x = lo + (top 53 bits of the engine output) * 2^-53 * (hi - lo), then y.
  std::mt19937_64 engine(1234);
  const double ux = static_cast<double>(engine() >> 11) * 0x1.0p-53;
  const double uy = static_cast<double>(engine() >> 11) * 0x1.0p-53;
  const auto seeds = randomSeeds(Rectangle{Vec3(-2, 1, 0), Vec3(2, 3, 0)}, 5, 1234);
  REQUIRE(seeds.size() == 5);
  CHECK(seeds[0].x() == -2 + ux * 4);
  CHECK(seeds[0].y() == 1 + uy * 2);
  CHECK(seeds[0].z() == 0);
}

TEST_CASE("random seeds are reproducible, inside the domain and uniform", "[seeds]") {
  const std::size_t n = 20000;
  const Box box{Vec3(0, 0, 0), Vec3(2, 4, 6)};
  const auto a = randomSeeds(box, n, 77);
  CHECK(a == randomSeeds(box, n, 77));
  CHECK(a != randomSeeds(box, n, 78));
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : a) {
    CHECK(((p - box.min).array() >= 0).all());
    CHECK(((box.max - p).array() >= 0).all());
    mean += p / n;
  }
  // Mean of a uniform variable on [0, L]: L/2 with standard deviation L/sqrt(12 n).
  for (int axis = 0; axis < 3; ++axis) {
    const double L = box.max[axis];
    CHECK(std::abs(mean[axis] - L / 2) < 5 * L / std::sqrt(12.0 * n));
  }

  Disk disk{Vec3(1, 1, 0), 2, 32};
  const auto d = randomSeeds(disk, 5000, 3);
  int inner = 0;
  for (const Vec3& p : d) {
    CHECK((p - disk.center).norm() <= 2);
    CHECK(p.z() == 0);
    if ((p - disk.center).norm() < 1) ++inner;
  }
  // A quarter of the area lies within half the radius (up to the 32-gon).
  CHECK(std::abs(inner / 5000.0 - 0.25) < 0.03);

  Ball ball{Vec3(0, 0, 1), 1, 3};
  for (const Vec3& p : randomSeeds(ball, 2000, 9)) CHECK((p - ball.center).norm() <= 1);
  CHECK(randomSeeds(ball, 0, 9).empty());
}

TEST_CASE("readSeedsCsv reads 2D and 3D rows with an optional header", "[seeds][csv]") {
  const auto p2 = writeTemp("ok2.csv", "x,y\n# a comment\n0.5, 0.25\n\n1e-1,+2\r\n");
  const auto s2 = readSeedsCsv(p2, 2);
  REQUIRE(s2.size() == 2);
  CHECK(s2[0] == Vec3(0.5, 0.25, 0));
  CHECK(s2[1] == Vec3(0.1, 2, 0));
  const auto p3 = writeTemp("ok3.csv", "1,2,3\n-4,5.5,6\n");
  const auto s3 = readSeedsCsv(p3, 3);
  REQUIRE(s3.size() == 2);
  CHECK(s3[1] == Vec3(-4, 5.5, 6));
}

TEST_CASE("readSeedsCsv errors name the file, line and value", "[seeds][csv][errors]") {
  const auto bad = writeTemp("bad.csv", "x,y\n0.1,0.2\n0.3,abc\n");
  CHECK_THROWS_WITH(readSeedsCsv(bad, 2), Catch::Contains(bad + ":3") && Catch::Contains("'abc'"));
  const auto cols = writeTemp("cols.csv", "0.1,0.2\n0.3,0.4,0.5\n");
  CHECK_THROWS_WITH(readSeedsCsv(cols, 2), Catch::Contains(cols + ":2") && Catch::Contains("got 3"));
  const auto nan = writeTemp("nan.csv", "1,2,3\n4,nan,6\n");
  CHECK_THROWS_WITH(readSeedsCsv(nan, 3), Catch::Contains(nan + ":2") && Catch::Contains("finite"));
  const auto empty = writeTemp("empty.csv", "x,y\n");
  CHECK_THROWS_WITH(readSeedsCsv(empty, 2), Catch::Contains("no seeds"));
  CHECK_THROWS_WITH(readSeedsCsv("/nonexistent/seeds.csv", 2), Catch::Contains("/nonexistent/seeds.csv"));
  CHECK_THROWS_AS(readSeedsCsv(bad, 4), InputError);
}

TEST_CASE("readSeedsCsv never takes a first row of data for a header", "[seeds][csv][errors]") {
  // A header names every column (letters first); anything else on the first row is data, checked as such.
  const auto names = writeTemp("names.csv", "# seeds\nx_um, Y\n1,2\n3,4\n");
  CHECK(readSeedsCsv(names, 2).size() == 2);
  const auto mixed = writeTemp("mixed.csv", "0.5,y\n1,2\n3,4\n");
  CHECK_THROWS_WITH(readSeedsCsv(mixed, 2), Catch::Contains(mixed + ":1, column 2: 'y'") &&
                                                Catch::Contains("header row names every column (x,y)"));
  const auto typo = writeTemp("typo.csv", "1.5x,2\n3,4\n");
  CHECK_THROWS_WITH(readSeedsCsv(typo, 2), Catch::Contains(typo + ":1, column 1: '1.5x' is not a number"));
  const auto nan = writeTemp("nan_first.csv", "nan,1,2\n3,4,5\n");
  CHECK_THROWS_WITH(readSeedsCsv(nan, 3), Catch::Contains(nan + ":1, column 1") && Catch::Contains("finite"));
  const auto empty = writeTemp("empty_field.csv", ",1\n3,4\n");
  CHECK_THROWS_WITH(readSeedsCsv(empty, 2), Catch::Contains(empty + ":1, column 1: '' is not a number"));
}
