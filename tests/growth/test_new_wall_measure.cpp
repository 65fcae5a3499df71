#include <catch2/catch.hpp>

#include <cmath>

#include "growth_fixtures.hpp"
#include "tessella/growth/new_wall_measure.hpp"
#include "tessella/growth/shortest_wall_search.hpp"
#include "tessella/tissue/builders.hpp"

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
