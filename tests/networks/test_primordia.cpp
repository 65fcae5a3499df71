// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Primordium detection (networks/primordia.hpp) on a synthetic tissue: a
// square lattice of cells whose concentration is a sum of Gaussian bumps at
// chosen lattice points, so the local maxima, their angles about the axis
// and the divergence angles are known by hand.

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "tessella/networks/primordia.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using namespace tessella::networks;

namespace {

struct Bump {
  double x, y, height;
};

// (2n+1)^2 cells at integer points (i, j), |i|, |j| <= n, on the plane z = 0;
// cell index (i + n) * (2n + 1) + (j + n); interfaces between 4-neighbours.
NetworkGraph lattice(int n) {
  NetworkGraph g;
  const int w = 2 * n + 1;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      g.measure.push_back(1.0);
      g.centroid.push_back(Vec3(i, j, 0));
    }
  for (int a = 0; a < w; ++a)
    for (int b = 0; b < w; ++b) {
      if (a + 1 < w) g.interfaces.push_back({a * w + b, (a + 1) * w + b, 1.0, Vec3(1, 0, 0)});
      if (b + 1 < w) g.interfaces.push_back({a * w + b, a * w + b + 1, 1.0, Vec3(0, 1, 0)});
    }
  return g;
}

int cellAt(int n, int i, int j) { return (i + n) * (2 * n + 1) + (j + n); }

std::vector<double> bumps(const NetworkGraph& g, const std::vector<Bump>& peaks) {
  std::vector<double> c;
  for (const Vec3& x : g.centroid) {
    double v = 1.0;
    for (const Bump& p : peaks) {
      const double dx = x.x() - p.x, dy = x.y() - p.y;
      v += p.height * std::exp(-(dx * dx + dy * dy));
    }
    c.push_back(v);
  }
  return c;
}

}  // namespace

TEST_CASE("axial position: angle counterclockwise about the axis from the projected x axis, distance from it",
          "[networks][primordia]") {
  const Vec3 apex(0, 0, 2.5);
  AxialPosition p = axialPosition(Vec3(1, 1, 5), apex, Vec3(0, 0, 1));
  CHECK(p.angle_deg == Approx(45).margin(1e-12));
  CHECK(p.radius == Approx(std::sqrt(2.0)));
  CHECK(p.distance == Approx(std::sqrt(2.0 + 2.5 * 2.5)));
  p = axialPosition(Vec3(-3, 0, 0), apex, Vec3(0, 0, 2));  // the axis need not be unit
  CHECK(p.angle_deg == Approx(180));
  CHECK(p.radius == Approx(3));
  // Looking down -z the turn is the other way: +y is at 270 degrees.
  p = axialPosition(Vec3(0, 1, 0), apex, Vec3(0, 0, -1));
  CHECK(p.angle_deg == Approx(270));
  // Axis along x: the reference is the y axis, and z is at 90 degrees (x cross y).
  p = axialPosition(Vec3(5, 0, 2), Vec3::Zero(), Vec3(1, 0, 0));
  CHECK(p.angle_deg == Approx(90));
  CHECK(p.radius == Approx(2));
}

TEST_CASE("divergence angle: the turn from one primordium to the next in [0, 360)", "[networks][primordia]") {
  CHECK(divergenceDeg(350, 127.5) == Approx(137.5));
  CHECK(divergenceDeg(10, 190) == Approx(180));
  CHECK(divergenceDeg(137.5, 0) == Approx(222.5));
  CHECK(divergenceDeg(42, 42) == 0);
}

TEST_CASE("primordia: strict local maxima above the threshold in the annulus, apart from the others",
          "[networks][primordia]") {
  const int n = 10;
  const NetworkGraph g = lattice(n);
  const std::vector<Bump> peaks{
      {5, 0, 10},   // angle 0, radius 5: taken first
      {-4, 4, 9},   // angle 135, radius sqrt(32): second
      {0, -5, 7},   // angle 270, radius 5: third
      {5, 2, 8},    // a maximum 2 from the first (min_separation 2.5): left out
      {0, 0, 20},   // the summit, radius 0 < min_radius
      {9, 0, 20},   // radius 9 > max_radius
      {0, 5, 0.5},  // below the threshold (1.5 + tails < 3)
      {-5, -1, 6},  // 1.1 from an existing primordium
  };
  const std::vector<double> c = bumps(g, peaks);
  PrimordiumOptions o;
  o.threshold = 3;
  o.min_radius = 2;
  o.max_radius = 7;
  o.min_separation = 2.5;
  o.apex = Vec3(0, 0, 0);
  const std::vector<Vec3> existing{Vec3(-4.5, -2, 0)};
  const std::vector<int> found = findPrimordia(g, c, o, existing);
  REQUIRE(found == std::vector<int>{cellAt(n, 5, 0), cellAt(n, -4, 4), cellAt(n, 0, -5)});
  std::vector<double> angles;
  for (int k : found)
    angles.push_back(axialPosition(g.centroid[static_cast<std::size_t>(k)], o.apex, o.axis).angle_deg);
  CHECK(angles[0] == Approx(0).margin(1e-12));
  CHECK(angles[1] == Approx(135));
  CHECK(angles[2] == Approx(270));
  CHECK(divergenceDeg(angles[0], angles[1]) == Approx(135));
  CHECK(divergenceDeg(angles[1], angles[2]) == Approx(135));

  SECTION("without the separation the close maximum is a primordium too, after the higher ones") {
    o.min_separation = 0;
    const std::vector<int> all = findPrimordia(g, c, o, {});
    REQUIRE(all == std::vector<int>{cellAt(n, 5, 0), cellAt(n, -4, 4), cellAt(n, 5, 2), cellAt(n, 0, -5),
                                    cellAt(n, -5, -1)});
  }
  SECTION("an existing primordium near a peak keeps it out") {
    const std::vector<Vec3> near{Vec3(5, 1, 0), Vec3(-4, 3, 0), Vec3(0, -4, 0), Vec3(-5, 0, 0)};
    const std::vector<int> none = findPrimordia(g, c, o, near);
    CHECK(none.empty());
  }
  SECTION("the annulus is in the distance from the apex: the same peaks far below it are out") {
    NetworkGraph below = g;
    for (Vec3& x : below.centroid) x.z() = -10;
    CHECK(findPrimordia(below, c, o, existing).empty());
  }
  SECTION("a plateau (two equal neighbours) is not a strict maximum") {
    std::vector<double> flat(g.numCells(), 1.0);
    flat[static_cast<std::size_t>(cellAt(n, 5, 0))] = 10;
    flat[static_cast<std::size_t>(cellAt(n, 5, 1))] = 10;
    CHECK(findPrimordia(g, flat, o, {}).empty());
  }
}

TEST_CASE("primordia: bad options and sizes are errors naming them", "[networks][primordia]") {
  PrimordiumOptions o;
  o.min_radius = 3;
  o.max_radius = 2;
  CHECK_THROWS_WITH(o.validate(), Catch::Contains("max_radius = 2"));
  o.max_radius = 4;
  o.axis = Vec3::Zero();
  CHECK_THROWS_WITH(o.validate(), Catch::Contains("axis"));
  o.axis = Vec3(0, 0, 1);
  CHECK_NOTHROW(o.validate());
  const NetworkGraph g = lattice(1);
  CHECK_THROWS_WITH(findPrimordia(g, {1.0, 2.0}, o, {}), Catch::Contains("2 concentrations for 9 cells"));
}
