// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "growth_fixtures.hpp"
#include "tessella/growth/besson_dumais_rule.hpp"
#include "tessella/growth/division_walls.hpp"
#include "tessella/growth/fixed_direction_rule.hpp"
#include "tessella/growth/main_axis_rule.hpp"
#include "tessella/growth/perpendicular_wall_rule.hpp"
#include "tessella/growth/random_direction_rule.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/growth/shortest_wall_rule.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::growth;
using Catch::Matchers::Contains;

namespace {

// Splits cell 0 with the rule; checks the daughters add up to the mother.
CellSplit splitAndCheck(Tissue& t, const DivisionRule& rule, Rng& rng) {
  const double mother = cellMeasure(t, CellId(0));
  const CellSplit s = t.splitCell(CellId(0), rule.plane(t, CellId(0), rng));
  const double sum = cellMeasure(t, CellId(0)) + cellMeasure(t, s.daughter);
  CHECK(std::abs(sum - mother) <= 1e-12 * mother);
  REQUIRE(validate(t).ok);
  return s;
}

double alignment(const Vec3& a, const Vec3& b) { return std::abs(a.normalized().dot(b.normalized())); }

}  // namespace

TEST_CASE("a 2:1 rectangle divides across its long side", "[growth][rules]") {
  Rng rng(1);
  for (const char* name : {"main_axis", "shortest_wall", "besson_dumais"}) {
    INFO(name);
    Tissue t = testing::rectangleCell(2.0, 1.0);
    const ParamValues params = std::string(name) == "besson_dumais" ? ParamValues{{"beta", 50.0}} : ParamValues{};
    auto rule = makeDivisionRule(name, params);
    const Plane p = rule->plane(t, CellId(0), rng);
    CHECK(alignment(p.normal, Vec3::UnitX()) == Approx(1.0).margin(1e-12));
    CHECK(p.point.isApprox(Vec3(1.0, 0.5, 0.0)));
    const CellSplit s = splitAndCheck(t, *rule, rng);
    CHECK(cellMeasure(t, CellId(0)) == Approx(1.0));
    CHECK(cellMeasure(t, s.daughter) == Approx(1.0));
    CHECK(wallMeasure(t, s.wall) == Approx(1.0));
  }
}

TEST_CASE("a square's shortest wall is a side-parallel midline", "[growth][rules]") {
  Tissue t = testing::rectangleCell(1.5, 1.5);
  Rng rng(2);
  const NewWallMeasure m(t, CellId(0));
  const auto minima = newWallLocalMinima(m);
  REQUIRE(minima.size() == 2);  // the two midlines; the diagonals are maxima
  for (const WallCandidate& w : minima) {
    CHECK(w.measure == Approx(1.5).epsilon(1e-12));
    CHECK(std::max(alignment(w.normal, Vec3::UnitX()), alignment(w.normal, Vec3::UnitY())) ==
          Approx(1.0).margin(1e-14));
  }
  const CellSplit s = splitAndCheck(t, ShortestWallRule{}, rng);
  CHECK(wallMeasure(t, s.wall) == Approx(1.5).epsilon(1e-9));
}

TEST_CASE("a regular hexagon's three midlines are equally short", "[growth][rules]") {
  const double R = 1.3;
  Tissue t = testing::hexagonCell(R, 0.17);  // rotated: no midline along an axis of the frame
  const BessonDumaisRule bd(3.0);
  const auto cands = bd.candidates(t, CellId(0));
  REQUIRE(cands.size() == 3);
  for (const auto& [w, p] : cands) {
    CHECK(w.measure == Approx(std::sqrt(3.0) * R).epsilon(1e-12));  // edge midpoint to midpoint
    CHECK(p == Approx(1.0 / 3.0).epsilon(1e-9));
  }
  // Pairwise 60 degrees apart, each through opposite edge midpoints: the
  // normal points at a vertex (angle phase + k pi/3).
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(alignment(cands[i].first.normal, cands[(i + 1) % 3].first.normal) == Approx(0.5).margin(1e-9));
    const double angle = std::atan2(cands[i].first.normal.y(), cands[i].first.normal.x()) - 0.17;
    CHECK(std::abs(std::remainder(angle, M_PI / 3)) < 1e-9);  // the search's tolerance is 1e-12 rad
  }
}

TEST_CASE("Besson-Dumais picks candidates with the Boltzmann weights", "[growth][rules]") {
  // A 1.2 x 1 rectangle: two local minima, lengths 1 and 1.2.
  Tissue t = testing::rectangleCell(1.2, 1.0);
  const double beta = 4.0;
  const BessonDumaisRule bd(beta);
  const auto cands = bd.candidates(t, CellId(0));
  REQUIRE(cands.size() == 2);
  CHECK(cands[0].first.measure == Approx(1.0));
  CHECK(cands[1].first.measure == Approx(1.2));
  const double p_short = 1.0 / (1.0 + std::exp(-beta * 0.2));
  CHECK(cands[0].second == Approx(p_short).epsilon(1e-9));
  Rng rng(7);
  int shortest = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i)
    if (alignment(bd.plane(t, CellId(0), rng).normal, Vec3::UnitX()) > 0.99) ++shortest;
  // Binomial standard deviation ~ 0.0035; allow 5 sigma.
  CHECK(static_cast<double>(shortest) / n == Approx(p_short).margin(0.018));
  CHECK_THROWS_AS(BessonDumaisRule(-1.0), InputError);
}

TEST_CASE("a 2:1:1 box divides across its long axis", "[growth][rules]") {
  Rng rng(3);
  for (const char* name : {"main_axis", "shortest_wall"}) {
    INFO(name);
    Tissue t = testing::boxCell(2.0, 1.0, 1.0);
    auto rule = makeDivisionRule(name);
    const Plane p = rule->plane(t, CellId(0), rng);
    CHECK(alignment(p.normal, Vec3::UnitX()) == Approx(1.0).margin(1e-6));
    const CellSplit s = splitAndCheck(t, *rule, rng);
    CHECK(wallMeasure(t, s.wall) == Approx(1.0).epsilon(1e-6));
    CHECK(cellMeasure(t, s.daughter) == Approx(1.0).epsilon(1e-6));
  }
}

TEST_CASE("3D shortest wall finds the smallest section of a flat box", "[growth][rules]") {
  // 3 x 2 x 1: sections through the centre perpendicular to x, y, z have areas
  // 2, 3, 6; the minimum is across x.
  Tissue t = testing::boxCell(3.0, 2.0, 1.0);
  const NewWallMeasure m(t, CellId(0));
  const auto minima = newWallLocalMinima(m);
  CHECK(minima.front().measure == Approx(2.0).epsilon(1e-8));
  CHECK(alignment(minima.front().normal, Vec3::UnitX()) == Approx(1.0).margin(1e-6));
}

TEST_CASE("shortest_wall's planes are its local minima, smallest section first", "[growth][rules]") {
  // 3 x 2 x 1 box: the sections through the centre across x, y, z (areas 2, 3, 6) are its three local minima;
  // the first plane is plane()'s, bit for bit; a rule with one plane gives plane() alone.
  Tissue t = testing::boxCell(3.0, 2.0, 1.0);
  Rng rng(3);
  const ShortestWallRule rule;
  const std::vector<Plane> planes = rule.planes(t, CellId(0), rng);
  REQUIRE(planes.size() == 3);
  const Plane first = rule.plane(t, CellId(0), rng);
  CHECK(planes[0].normal == first.normal);
  CHECK(planes[0].point == first.point);
  const Vec3 axes[3] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  const double areas[3] = {2.0, 3.0, 6.0};
  const NewWallMeasure m(t, CellId(0));
  for (int i = 0; i < 3; ++i) {
    CHECK(alignment(planes[i].normal, axes[i]) == Approx(1.0).margin(1e-9));
    CHECK(m.measure(planes[i].normal) == Approx(areas[i]).epsilon(1e-12));
    CHECK((planes[i].point - Vec3(1.5, 1.0, 0.5)).norm() < 1e-12);
  }
  const MainAxisRule main_axis;
  const std::vector<Plane> one = main_axis.planes(t, CellId(0), rng);
  REQUIRE(one.size() == 1);
  CHECK(one[0].normal == main_axis.plane(t, CellId(0), rng).normal);
}

TEST_CASE("the new wall meets the mother wall at right angles", "[growth][rules]") {
  // A 4 x 1 strip divided across x gives two 2 x 1 daughters whose birth wall
  // is the line x = 2. Main axis would cut them across x again; the
  // Hofmeister/Sachs rule cuts them along y = 1/2, perpendicular to that wall.
  Tissue t = testing::rectangleCell(4.0, 1.0);
  Rng rng(4);
  auto& tags = divisionWallTags(t);
  const std::int64_t mother = t.lineageId(CellId(0));
  const CellSplit first = t.splitCell(CellId(0), Plane{Vec3(2, 0.5, 0), Vec3::UnitX()});
  tags[first.wall] = mother;
  const CellId a(0), b = first.daughter;
  REQUIRE(birthWalls(t, a).size() == 1);
  REQUIRE(birthWalls(t, b).size() == 1);

  const double tol = 0.05;
  const PerpendicularWallRule rule(tol);
  const Plane pa = rule.plane(t, a, rng);
  CHECK(alignment(pa.normal, Vec3::UnitY()) == Approx(1.0).margin(1e-12));
  CHECK(pa.point.y() == Approx(0.5));
  const CellSplit sa = t.splitCell(a, pa);
  tags[sa.wall] = t.parentId(a);
  // The sister's centroid line would meet the wall at the new junction (2, 0.5):
  // the plane is shifted by the tolerance instead of making a four-way junction.
  const Plane pb = rule.plane(t, b, rng);
  const double size = std::sqrt(cellMeasure(t, b));
  CHECK(alignment(pb.normal, Vec3::UnitY()) == Approx(1.0).margin(1e-12));
  CHECK(std::abs(pb.point.y() - 0.5) == Approx(tol * size).epsilon(1e-9));
  t.splitCell(b, pb);
  REQUIRE(validate(t).ok);
  for (VertexId v : t.vertices()) CHECK(t.topology().vertexEdges(v).size() <= 3);
}

TEST_CASE("founder cells fall back to the main axis", "[growth][rules]") {
  Tissue t = testing::rectangleCell(3.0, 1.0);
  Rng rng(5);
  const Plane p = PerpendicularWallRule().plane(t, CellId(0), rng);
  CHECK(alignment(p.normal, Vec3::UnitX()) == Approx(1.0));
}

TEST_CASE("random directions are uniform", "[growth][rules]") {
  Rng rng(6);
  const RandomDirectionRule rule;
  const int n = 20000;
  SECTION("2D: uniform angle in the plane") {
    Tissue t = testing::rectangleCell(1.0, 1.0);
    double mean_abs_cos = 0;
    for (int i = 0; i < n; ++i) {
      const Plane p = rule.plane(t, CellId(0), rng);
      REQUIRE(p.normal.z() == 0.0);
      mean_abs_cos += std::abs(p.normal.x()) / n;
    }
    CHECK(mean_abs_cos == Approx(2.0 / M_PI).margin(0.01));  // E|cos| for a uniform angle
  }
  SECTION("3D: uniform on the sphere") {
    Tissue t = testing::boxCell(1.0, 1.0, 1.0);
    double mean_z = 0, mean_z2 = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3 nz = rule.plane(t, CellId(0), rng).normal;
      mean_z += nz.z() / n;
      mean_z2 += nz.z() * nz.z() / n;
    }
    CHECK(mean_z == Approx(0.0).margin(0.02));
    CHECK(mean_z2 == Approx(1.0 / 3.0).margin(0.01));
  }
}

TEST_CASE("fixed direction, and its impossible case on a surface", "[growth][rules]") {
  Rng rng(8);
  Tissue t = testing::rectangleCell(1.0, 1.0);
  const FixedDirectionRule rule(Vec3(1, 1, 5));  // the z part is dropped in the plane
  const Plane p = rule.plane(t, CellId(0), rng);
  CHECK(p.normal.isApprox(Vec3(1, 1, 0).normalized()));
  Tissue cap = testing::sphericalCapGrid(3, 0.3, 10.0);
  const CellId centre(4);
  const Vec3 normal = polygonMeasures(cap, cap.cellFace(centre)).normal;
  CHECK_THROWS_WITH(FixedDirectionRule(normal).plane(cap, centre, rng), Contains("cell 4"));
  CHECK_THROWS_AS(FixedDirectionRule(Vec3::Zero()), InputError);
}

TEST_CASE("on a surface every rule's plane contains the cell normal", "[growth][rules]") {
  Tissue cap = testing::sphericalCapGrid(4, 1.6, 2.0);
  Rng rng(9);
  for (const std::string& name : divisionRuleNames()) {
    INFO(name);
    auto rule = makeDivisionRule(
        name, name == "fixed" ? ParamValues{{"fixed_normal", std::vector<double>{1, 0.3, 0}}} : ParamValues{});
    for (CellId c : cap.cells()) {
      const Vec3 n = polygonMeasures(cap, cap.cellFace(c)).normal;
      const Plane p = rule->plane(cap, c, rng);
      CHECK(std::abs(p.normal.normalized().dot(n)) < 1e-12);
    }
  }
  // And it divides every cell of the cap.
  auto rule = makeDivisionRule("shortest_wall");
  const double total = totalMeasure(cap);
  std::vector<CellId> cells;
  for (CellId c : cap.cells()) cells.push_back(c);
  for (CellId c : cells) cap.splitCell(c, rule->plane(cap, c, rng));
  CHECK(cap.numCells() == 32);
  CHECK(totalMeasure(cap) == Approx(total).epsilon(1e-3));  // non-planar fans change slightly
  CHECK(validate(cap).ok);
}

TEST_CASE("unknown rule names are input errors listing the known ones", "[growth][rules]") {
  CHECK_THROWS_WITH(makeDivisionRule("errera"), Contains("'errera'") && Contains("shortest_wall"));
}

namespace {

// A 64-gon on the ellipse with semi-axes a > b, its major axis at angle phi
// (counter-clockwise from x): its main axis is exactly the major axis.
Tissue ellipseCell(double a, double b, double phi) {
  std::vector<Vec3> p;
  std::vector<Index> loop;
  for (int i = 0; i < 64; ++i) {
    const double s = 2 * M_PI * i / 64, x = a * std::cos(s), y = b * std::sin(s);
    p.emplace_back(x * std::cos(phi) - y * std::sin(phi), x * std::sin(phi) + y * std::cos(phi), 0);
    loop.push_back(static_cast<Index>(i));
  }
  return buildPolygonTissue(p, {loop});
}

double radians(double degrees) { return degrees * M_PI / 180; }

// Every vertex moved by up to `amount` in each direction (z too when `in_z`).
void jitter(Tissue& t, double amount, bool in_z, std::uint64_t seed) {
  Rng rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (Vec3& x : t.mutablePositions()) x += Vec3(u(rng), u(rng), in_z ? u(rng) : 0.0);
}

}  // namespace

TEST_CASE("fixed_angle_to_main_axis turns the main-axis wall by the angle", "[growth][rules]") {
  // Rectangle 2 x 1 (main axis x) and an ellipse whose major axis is at 0.4 rad:
  // the plane normal is the major axis turned by the angle, counter-clockwise
  // seen from +z, and so is the new wall (the main-axis wall is across the major axis).
  Rng rng(10);
  for (const double phi : {0.0, 0.4}) {
    for (const double angle : {0.0, 30.0, -45.0, 60.0, 90.0, -90.0}) {
      INFO("phi " << phi << ", angle " << angle);
      Tissue t = phi == 0.0 ? testing::rectangleCell(2.0, 1.0) : ellipseCell(2.0, 1.0, phi);
      const Vec3 centroid = cellCentroid(t, CellId(0));
      const auto rule = makeDivisionRule("fixed_angle_to_main_axis", {{"angle", angle}});
      const Plane p = rule->plane(t, CellId(0), rng);
      const double turned = phi + radians(angle);
      CHECK(p.normal.z() == 0.0);
      CHECK(alignment(p.normal, Vec3(std::cos(turned), std::sin(turned), 0)) == Approx(1.0).margin(1e-12));
      CHECK((p.point - centroid).norm() < 1e-12);
      // The signed angle from the main-axis plane, modulo pi.
      const Vec3 n0 = MainAxisRule().plane(t, CellId(0), rng).normal;
      const double signed_angle = std::atan2(n0.cross(p.normal).z(), n0.dot(p.normal));
      CHECK(std::abs(std::remainder(signed_angle - radians(angle), M_PI)) < 1e-12);
      // The new wall runs along the main-axis wall turned by the angle.
      const CellSplit s = splitAndCheck(t, *rule, rng);
      const auto ends = t.topology().edgeVertices(EdgeId(s.wall.index()));
      const Vec3 wall = t.position(ends[1]) - t.position(ends[0]);
      CHECK(alignment(wall, Vec3(-std::sin(turned), std::cos(turned), 0)) == Approx(1.0).margin(1e-12));
      CHECK(wall.normalized().cross(centroid - t.position(ends[0])).norm() < 1e-12);  // through the centroid
    }
  }
}

TEST_CASE("fixed_angle_to_main_axis at angle 0 is the main-axis rule, bit for bit", "[growth][rules]") {
  Tissue sheet = hexagonalGrid(6, 5, 1.0);
  jitter(sheet, 0.2, false, 11);
  Tissue box = boxGrid(3, 3, 2, 1.5, 1.0, 0.8);
  jitter(box, 0.1, true, 12);
  Tissue cap = testing::sphericalCapGrid(4, 1.6, 2.0);
  Rng rng(13);
  const auto zero = makeDivisionRule("fixed_angle_to_main_axis");  // the default angle is 0
  const MainAxisRule main_axis;
  for (const Tissue* t : {&sheet, &box, &cap}) {
    for (CellId c : t->cells()) {
      const Plane a = zero->plane(*t, c, rng), b = main_axis.plane(*t, c, rng);
      CHECK(a.point == b.point);
      CHECK(a.normal == b.normal);
    }
  }
}

TEST_CASE("fixed_angle_to_main_axis on a curved sheet and in 3D", "[growth][rules]") {
  Rng rng(14);
  SECTION("curved sheet: turned about the cell normal, within the tangent plane") {
    Tissue cap = testing::sphericalCapGrid(4, 1.6, 2.0);
    jitter(cap, 0.03, false, 15);  // cells with a definite main axis
    const double angle = 35.0;
    const auto rule = makeDivisionRule("fixed_angle_to_main_axis", {{"angle", angle}});
    for (CellId c : cap.cells()) {
      const Vec3 normal = polygonMeasures(cap, cap.cellFace(c)).normal.normalized();
      const Vec3 n0 = MainAxisRule().plane(cap, c, rng).normal, n = rule->plane(cap, c, rng).normal;
      CHECK(std::abs(n.dot(normal)) < 1e-12);
      const double signed_angle = std::atan2(n0.cross(n).dot(normal), n0.dot(n));
      CHECK(std::abs(std::remainder(signed_angle - radians(angle), M_PI)) < 1e-9);
    }
  }
  SECTION("3D: a 3 x 2 x 1 box turns about its shortest axis z") {
    for (const double angle : {0.0, 30.0, 90.0}) {
      INFO(angle);
      Tissue t = testing::boxCell(3.0, 2.0, 1.0);
      const auto rule = makeDivisionRule("fixed_angle_to_main_axis", {{"angle", angle}});
      const Plane p = rule->plane(t, CellId(0), rng);
      // n = cos a x + sin a (z x x) = (cos a, sin a, 0), up to the sign of the whole normal.
      CHECK(alignment(p.normal, Vec3(std::cos(radians(angle)), std::sin(radians(angle)), 0)) ==
            Approx(1.0).margin(1e-12));
      const CellSplit s = splitAndCheck(t, *rule, rng);
      const Vec3 wall_normal = polygonMeasures(t, FaceId(s.wall.index())).normal;
      CHECK(alignment(wall_normal, p.normal) == Approx(1.0).margin(1e-12));
      CHECK(cellMeasure(t, s.daughter) == Approx(3.0).epsilon(1e-12));  // through the centroid of a box
    }
  }
  CHECK_THROWS_WITH(makeDivisionRule("fixed_angle_to_main_axis", {{"angle", 120.0}}),
                    Contains("parameter 'angle' must be a number >= -90 and <= 90, got 120.0"));
}
