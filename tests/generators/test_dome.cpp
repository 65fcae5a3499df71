// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Dome tissues: a footprint Voronoi tissue lifted onto a spherical cap or a
// paraboloid; every vertex must lie on the analytic surface.

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "tessella/generators/dome.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;

TEST_CASE("a spherical-cap dome has every vertex on its sphere", "[dome]") {
  Dome dome;
  dome.base_center = Vec3(2, -1, 0.5);
  dome.base_radius = 3;
  dome.height = 1.2;
  const auto seeds = randomSeeds(Disk{Vec3(2, -1, 0), 3, 256}, 250, 17);
  const Tissue t = domeTissue(seeds, dome);
  REQUIRE(t.embedding() == Embedding::Surface);
  REQUIRE(t.numCells() == seeds.size());
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);

  // Sphere through the base circle and the summit.
  const double R = (3.0 * 3.0 + 1.2 * 1.2) / (2 * 1.2);
  const Vec3 centre = dome.base_center + Vec3(0, 0, 1.2 - R);
  for (VertexId v : t.vertices()) {
    const Vec3& p = t.position(v);
    CHECK(std::abs((p - centre).norm() - R) <= 1e-12 * R);
    CHECK(p.z() >= dome.base_center.z() - 1e-12);
  }
  // Lifting only raises vertices: the curved sheet is larger than its footprint.
  CHECK(totalMeasure(t) > 256 / 2.0 * 9 * std::sin(2 * std::numbers::pi / 256));
  CHECK(dome.heightAt(0) == Approx(1.2));
  CHECK(dome.heightAt(3) == Approx(0).margin(1e-14));
}

TEST_CASE("a paraboloid dome has every vertex on its paraboloid", "[dome]") {
  Dome dome;
  dome.shape = Dome::Shape::Paraboloid;
  dome.base_radius = 1;
  dome.height = 2;  // taller than wide is fine for a paraboloid
  const auto seeds = randomSeeds(Disk{}, 150, 4);
  VoronoiOptions options;
  options.lloyd_iterations = 3;
  const Tissue t = domeTissue(seeds, dome, options);
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  for (VertexId v : t.vertices()) {
    const Vec3& p = t.position(v);
    const double r2 = p.x() * p.x() + p.y() * p.y();
    CHECK(p.z() == Approx(2 * (1 - r2)).margin(1e-12));
  }
}

TEST_CASE("a dome's whole rim lies on its base circle, in the base plane", "[dome]") {
  // The footprint is a 256-gon inscribed in the circle: before the rim was put on the circle, the rim vertices on
  // its sides sat up to 1e-4 R above the base plane.
  for (const Dome::Shape shape : {Dome::Shape::SphericalCap, Dome::Shape::Paraboloid}) {
    Dome dome;
    dome.shape = shape;
    dome.base_center = Vec3(2, -1, 0.5);
    dome.base_radius = 3;
    dome.height = 1.5;
    const Tissue t = domeTissue(randomSeeds(Disk{Vec3(2, -1, 0), 3, 256}, 400, 5), dome);
    const auto report = validate(t);
    INFO(report.message);
    REQUIRE(report.ok);
    std::size_t rim = 0, corners_only = 0;
    for (WallId w : t.walls()) {
      if (!t.isBoundaryWall(w)) continue;
      for (VertexId v : t.topology().edgeVertices(EdgeId(w.index()))) {
        const Vec3 d = t.position(v) - dome.base_center;
        CHECK(std::abs(d.z()) <= 1e-12);
        CHECK(std::abs(std::hypot(d.x(), d.y()) - 3.0) <= 1e-12 * 3.0);
        ++rim;
      }
    }
    // Every other vertex is inside the circle, above the plane.
    for (VertexId v : t.vertices()) {
      const Vec3 d = t.position(v) - dome.base_center;
      if (std::hypot(d.x(), d.y()) < 3.0 * (1 - 1e-9)) CHECK(d.z() > 0.0);
      else ++corners_only;
    }
    CHECK(rim > 2 * 256);  // each rim vertex counted by its two rim walls: more than the polygon's corners
    CHECK(corners_only == rim / 2);
  }
}

TEST_CASE("bad domes raise InputError naming the field", "[dome][errors]") {
  Dome cap;
  cap.height = 1.5;  // taller than the base radius: overhangs
  const auto seeds = randomSeeds(Disk{}, 20, 1);
  CHECK_THROWS_WITH(domeTissue(seeds, cap), Catch::Contains("dome.height"));
  Dome flat;
  flat.height = 0;
  CHECK_THROWS_AS(domeTissue(seeds, flat), InputError);
  Dome ok;
  CHECK_THROWS_WITH(ok.heightAt(1.5), Catch::Contains("1.5"));
  auto outside = seeds;
  outside[7] = Vec3(1.5, 0, 0);
  CHECK_THROWS_WITH(domeTissue(outside, ok), Catch::Contains("seed 7 "));
}
