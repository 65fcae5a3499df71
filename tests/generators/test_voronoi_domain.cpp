// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The ball's face groups (ConvexDomain3::groups): excess() skips the groups
// whose bound says they cannot hold the maximum, and must still return
// exactly the largest excess over every face -- compared with a plain scan.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>

#include "../../generators/src/voronoi_domain.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;

namespace {

double plainExcess(const detail::ConvexDomain3& d, const Vec3& p) {
  double worst = -std::numeric_limits<double>::infinity();
  for (const detail::HalfSpace& f : d.faces) worst = std::max(worst, f.normal.dot(p) - f.offset);
  return worst;
}

}  // namespace

TEST_CASE("a ball's grouped excess equals the largest excess over every face", "[voronoi][domain]") {
  std::mt19937_64 rng(19);
  std::normal_distribution<double> gauss(0, 1);
  for (int subdivisions : {2, 3, 4})
    for (double radius : {1.0, 1e-3, 250.0})
      for (const Vec3& center : {Vec3(0, 0, 0), Vec3(5, -3, 2), Vec3(1e6, 0, -1e6)}) {
        Ball ball;
        ball.center = center;
        ball.radius = radius;
        ball.subdivisions = subdivisions;
        const detail::ConvexDomain3 d = detail::makeDomain(ball);
        REQUIRE(d.groups.size() == 20);
        INFO("subdivisions " << subdivisions << " radius " << radius << " center " << center.transpose());
        // The centre, points on rays out to far away (circumcentres of flat
        // tetrahedra), and points within 1e-9 of a face's plane, where the
        // maximum may sit in a neighbouring group.
        int differ = 0;
        for (int i = 0; i < 20000; ++i) {
          const double along[] = {0.0, 0.5, 0.99, 1.0, 1.0000001, 1.01, 3.0, 1e3, 1e8};
          Vec3 p = center + radius * along[i % 9] * Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
          if (i % 5 == 0) {
            const detail::HalfSpace& f = d.faces[static_cast<std::size_t>(i) % d.faces.size()];
            const Vec3 tangent = f.normal.cross(Vec3(gauss(rng), gauss(rng), gauss(rng))).normalized();
            p = f.normal * f.offset + tangent * (0.1 * radius * gauss(rng)) + f.normal * (1e-9 * radius * gauss(rng));
          }
          differ += d.excess(p) != plainExcess(d, p);
        }
        CHECK(differ == 0);
      }
}

TEST_CASE("grouped excess is exact for any grouping of the faces", "[voronoi][domain]") {
  // The faces shuffled or sorted along x before grouping: cones that overlap
  // and whose axes do not say where the maximum is.
  std::mt19937_64 rng(23);
  std::normal_distribution<double> gauss(0, 1);
  Ball ball;
  ball.center = Vec3(0.5, -2, 1);
  ball.subdivisions = 3;
  for (int order = 0; order < 2; ++order)
    for (std::size_t count : {4, 16, 32}) {
      detail::ConvexDomain3 d = detail::makeDomain(ball);
      if (order == 0)
        std::shuffle(d.faces.begin(), d.faces.end(), rng);
      else
        std::sort(d.faces.begin(), d.faces.end(),
                  [](const detail::HalfSpace& a, const detail::HalfSpace& b) { return a.normal.x() < b.normal.x(); });
      detail::groupFaces(d, count);
      INFO("order " << order << " groups " << count);
      int differ = 0;
      for (int i = 0; i < 20000; ++i) {
        const double along[] = {0.0, 0.9, 1.0, 1.001, 2.0, 1e4};
        const Vec3 p = ball.center + along[i % 6] * Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
        differ += d.excess(p) != plainExcess(d, p);
      }
      CHECK(differ == 0);
    }
}

TEST_CASE("a box and a coarse ball scan every face", "[voronoi][domain]") {
  CHECK(detail::makeDomain(Box{}).groups.empty());
  Ball coarse;
  coarse.subdivisions = 1;
  CHECK(detail::makeDomain(coarse).groups.empty());
}
