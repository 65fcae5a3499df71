// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "growth_fixtures.hpp"
#include "tessella/growth/new_wall_measure.hpp"
#include "tessella/growth/shortest_wall_search.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;
using namespace tessella::growth;

TEST_CASE("chord lengths through a square's centre", "[growth][wall_measure]") {
  Tissue t = testing::rectangleCell(2.0, 2.0);
  const NewWallMeasure m(t, CellId(0));
  CHECK(m.point().isApprox(Vec3(1, 1, 0)));
  for (double theta : {0.0, 0.3, M_PI / 4, 1.0, M_PI / 2, 2.0, 3.0}) {
    const double expect = 2.0 / std::max(std::abs(std::cos(theta)), std::abs(std::sin(theta)));
    CHECK(m.length(theta) == Approx(expect).epsilon(1e-12));
  }
}

TEST_CASE("the chord through the point in a concave cell", "[growth][wall_measure]") {
  // A U shape: the horizontal line y = 2.5 crosses it twice (two arms); through
  // the point (0.5, 2.5) the chord is the left arm's, of length 1.
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 3, 0), Vec3(2, 3, 0),
                               Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 3, 0), Vec3(0, 3, 0)};
  Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3, 4, 5, 6, 7}});
  const NewWallMeasure m(t, CellId(0), Vec3(0.5, 2.5, 0));
  CHECK(m.measure(Vec3(0, 1, 0)) == Approx(1.0));
  CHECK(m.measure(Vec3(1, 0, 0)) == Approx(3.0));  // the vertical line x = 0.5
}

TEST_CASE("section areas of a unit cube through its centre", "[growth][wall_measure]") {
  Tissue t = testing::boxCell(1, 1, 1);
  const NewWallMeasure m(t, CellId(0));
  CHECK(m.point().isApprox(Vec3(0.5, 0.5, 0.5)));
  CHECK(m.measure(Vec3(0, 0, 1)) == Approx(1.0));
  CHECK(m.measure(Vec3(0, 0, -1)) == Approx(1.0));
  CHECK(m.measure(Vec3(1, 1, 0)) == Approx(std::sqrt(2.0)));
  // Perpendicular to a body diagonal: a regular hexagon of side sqrt(2)/2.
  CHECK(m.measure(Vec3(1, 1, 1)) == Approx(3 * std::sqrt(3.0) / 4));
}

TEST_CASE("Brent's method finds a smooth minimum to the tolerance", "[growth][wall_measure]") {
  const double x = brentMinimize([](double a) { return std::cos(a) + 0.1 * a; }, 2.0, 4.5, 1e-10);
  CHECK(x == Approx(M_PI - std::asin(0.1)).margin(1e-8));
  // A kink (|a - 1|): golden-section steps still converge.
  CHECK(brentMinimize([](double a) { return std::abs(a - 1.0); }, -3.0, 2.0, 1e-9) ==
        Approx(1.0).margin(1e-8));
}

namespace {

// Checks the 2D search against a dense sampling of L(theta): the global
// minimum agrees (the search cannot be beaten by any sample, and no sample
// is far below it), every candidate is a local minimum of L, and every
// sampled local minimum is one of the candidates.
void checkAgainstSampling(const NewWallMeasure& m) {
  const std::vector<WallCandidate> minima = newWallLocalMinima(m);
  REQUIRE(!minima.empty());
  const int n = 20000;
  const double step = M_PI / n;
  std::vector<double> len(n);
  for (int i = 0; i < n; ++i) len[i] = m.length(i * step);
  const double sampled_min = *std::min_element(len.begin(), len.end());
  const double scale = *std::max_element(len.begin(), len.end());
  CHECK(minima.front().measure <= sampled_min + 1e-12 * scale);
  // |dL/dtheta| <= L_max^2 / (2 * distance to the boundary): a loose bound
  // is enough to tell "found the minimum" from "missed it".
  CHECK(minima.front().measure >= sampled_min - 1e-3 * scale);
  for (const WallCandidate& w : minima) {
    INFO("candidate theta " << w.theta << " length " << w.measure);
    CHECK(w.measure == Approx(m.length(w.theta)).epsilon(1e-12));
    for (double d : {1e-4, -1e-4}) CHECK(m.length(w.theta + d) >= w.measure - 1e-12 * scale);
  }
  for (int i = 0; i < n; ++i) {
    const double prev = len[(i + n - 1) % n], next = len[(i + 1) % n];
    if (!(len[i] < prev && len[i] < next)) continue;
    const double theta = i * step;
    bool found = false;
    for (const WallCandidate& w : minima)
      found = found || std::abs(std::remainder(w.theta - theta, M_PI)) <= 2 * step;
    INFO("sampled local minimum at theta " << theta << " length " << len[i]);
    CHECK(found);
  }
}

}  // namespace

TEST_CASE("the exact 2D search agrees with dense sampling on Voronoi cells", "[growth][wall_measure]") {
  const Rectangle domain{Vec3(0, 0, 0), Vec3(10, 10, 0)};
  const Tissue t = voronoiTissue(randomSeeds(domain, 60, 11), domain);
  for (CellId c : t.cells()) {
    INFO("cell " << c.index());
    checkAgainstSampling(NewWallMeasure(t, c));
  }
}

TEST_CASE("the 2D search on concave cells", "[growth][wall_measure]") {
  SECTION("an L shape: the centroid is inside, some lines cross four times") {
    const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0),
                                 Vec3(1, 1, 0), Vec3(1, 3, 0), Vec3(0, 3, 0)};
    Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3, 4, 5}});
    checkAgainstSampling(NewWallMeasure(t, CellId(0)));
  }
  SECTION("an arrow head with a deep notch") {
    const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(4, 1.5, 0), Vec3(0, 3, 0), Vec3(1.5, 1.5, 0)};
    Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3}});
    checkAgainstSampling(NewWallMeasure(t, CellId(0)));
  }
  SECTION("a U shape through a point outside the cell (sampled fallback)") {
    const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 3, 0), Vec3(2, 3, 0),
                                 Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 3, 0), Vec3(0, 3, 0)};
    Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3, 4, 5, 6, 7}});
    const NewWallMeasure m(t, CellId(0), Vec3(1.5, 2.0, 0));  // in the notch
    const auto minima = newWallLocalMinima(m);
    const int n = 20000;
    double sampled_min = 1e300;
    for (int i = 0; i < n; ++i) sampled_min = std::min(sampled_min, m.length(i * M_PI / n));
    CHECK(minima.front().measure <= sampled_min + 1e-9);
  }
}

TEST_CASE("the 3D search is not beaten by a dense sampling of normals on Voronoi cells",
          "[growth][wall_measure]") {
  const Box domain{Vec3(0, 0, 0), Vec3(3, 3, 3)};
  const Tissue t = voronoiTissue(randomSeeds(domain, 12, 4), domain);
  for (CellId c : t.cells()) {
    INFO("cell " << c.index());
    const NewWallMeasure m(t, c);
    const auto minima = newWallLocalMinima(m);
    REQUIRE(!minima.empty());
    // Fibonacci points on the unit sphere: normals about 1.4 degrees apart.
    const int n = 20000;
    double sampled_min = 1e300;
    for (int i = 0; i < n; ++i) {
      const double z = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(1.0 - z * z);
      const double phi = i * M_PI * (3.0 - std::sqrt(5.0));
      sampled_min = std::min(sampled_min, m.measure(Vec3(r * std::cos(phi), r * std::sin(phi), z)));
    }
    CHECK(minima.front().measure <= sampled_min * (1 + 1e-9));
    for (const WallCandidate& w : minima) CHECK(w.measure == Approx(m.measure(w.normal)).epsilon(1e-12));
  }
}

TEST_CASE("the 3D section gradient", "[growth][wall_measure]") {
  SECTION("a unit cube near a face normal: A = 1 / n_x, closed-form gradient") {
    // A plane through the centre with normal near x crosses the four edges
    // along x: a parallelogram of area 1 / n_x, whose gradient on the sphere
    // is the tangent part of -e_x / n_x^2.
    Tissue t = testing::boxCell(1, 1, 1);
    const NewWallMeasure m(t, CellId(0));
    for (const Vec3& d : {Vec3(1, 0.2, 0.1), Vec3(1, -0.3, 0.25), Vec3(-1, 0.1, -0.4)}) {
      const Vec3 n = d.normalized();
      Vec3 g;
      const double a = m.measureAndGradient(n, g);
      CHECK(a == Approx(1 / std::abs(n.x())).epsilon(1e-13));
      const Vec3 ex = Vec3::UnitX() * (n.x() > 0 ? 1 : -1);
      const Vec3 expect = -(ex - n * n.dot(ex)) / (n.x() * n.x());
      CHECK((g - expect).norm() <= 1e-12 * expect.norm());
    }
  }
  SECTION("Voronoi cells: central differences along great circles") {
    const Box domain{Vec3(0, 0, 0), Vec3(3, 3, 3)};
    const Tissue t = voronoiTissue(randomSeeds(domain, 12, 4), domain);
    std::mt19937_64 rng(21);
    std::normal_distribution<double> normal;
    for (CellId c : t.cells()) {
      const NewWallMeasure m(t, c);
      for (int k = 0; k < 20; ++k) {
        const Vec3 n = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
        Vec3 g;
        const double a = m.measureAndGradient(n, g);
        INFO("cell " << c.index() << " normal " << n.transpose());
        CHECK(a == Approx(m.measure(n)).epsilon(1e-13));
        CHECK(std::abs(g.dot(n)) <= 1e-13 * a);  // tangent
        const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
        for (const Vec3& e : {e1, e2}) {
          // Turning by +-h along e: A is smooth unless the plane passes a
          // vertex within h, which a random normal does with probability ~ 1e-6.
          const double h = 1e-6;
          const double fd = (m.measure(std::cos(h) * n + std::sin(h) * e) -
                             m.measure(std::cos(h) * n - std::sin(h) * e)) / (2 * h);
          CHECK(g.dot(e) == Approx(fd).margin(1e-7 * a));
        }
      }
    }
  }
}

TEST_CASE("the 3D search finds every local minimum of a box", "[growth][wall_measure]") {
  // Through the centre of an a x b x c box the sections across the axes
  // (areas bc, ac, ab) are the local minima: tilting a plane off an axis
  // lengthens its section in the direction it tilts (as 1 / cos).
  Tissue t = testing::boxCell(3.0, 2.0, 1.0);
  const auto minima = newWallLocalMinima(NewWallMeasure(t, CellId(0)));
  REQUIRE(minima.size() == 3);
  const std::array<double, 3> area = {2.0, 3.0, 6.0};
  const std::array<Vec3, 3> axis = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  for (int i = 0; i < 3; ++i) {
    CHECK(minima[i].measure == Approx(area[i]).epsilon(1e-12));
    CHECK(std::abs(minima[i].normal.dot(axis[i])) == Approx(1.0).margin(1e-12));
  }
  // A cube: the three face normals, the saddles (edge and corner directions,
  // where the gradient vanishes) left behind.
  Tissue cube = testing::boxCell(1.0, 1.0, 1.0);
  const auto cube_minima = newWallLocalMinima(NewWallMeasure(cube, CellId(0)));
  REQUIRE(cube_minima.size() == 3);
  for (const WallCandidate& w : cube_minima) {
    CHECK(w.measure == Approx(1.0).epsilon(1e-12));
    CHECK(w.normal.cwiseAbs().maxCoeff() == Approx(1.0).margin(1e-12));
  }
}

TEST_CASE("every 3D candidate is a local minimum on Voronoi cells", "[growth][wall_measure]") {
  // Rings of normals 1e-4, 1e-3 and 1e-2 rad around each candidate: none has
  // a smaller section (to the search's tolerance, 1e-12 relative).
  const Box domain{Vec3(0, 0, 0), Vec3(3, 3, 3)};
  const Tissue t = voronoiTissue(randomSeeds(domain, 12, 4), domain);
  for (CellId c : t.cells()) {
    const NewWallMeasure m(t, c);
    for (const WallCandidate& w : newWallLocalMinima(m)) {
      const Vec3 e1 = w.normal.unitOrthogonal(), e2 = w.normal.cross(e1);
      double lowest = 1e300;
      for (double r : {1e-4, 1e-3, 1e-2})
        for (int k = 0; k < 24; ++k) {
          const double phi = 2 * M_PI * k / 24;
          lowest = std::min(lowest, m.measure(w.normal + r * (std::cos(phi) * e1 + std::sin(phi) * e2)));
        }
      INFO("cell " << c.index() << " candidate " << w.normal.transpose() << " area " << w.measure);
      CHECK(lowest >= w.measure * (1 - 1e-12));
    }
  }
}
