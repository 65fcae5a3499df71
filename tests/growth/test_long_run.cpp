// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <set>
#include <string>

#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/validate.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;
using namespace tessella::growth;

namespace {

// Grows and divides until `divisions` divisions happened, validating the
// tissue and the uniqueness of lineage ids after every step, and checking
// the total measure against the exact exp(dim r t) growth.
void run(Tissue t, const std::string& rule, double rate, std::size_t divisions) {
  INFO("rule " << rule << ", dim " << t.dim());
  const double m0 = totalMeasure(t), t0 = t.time();
  const double mean_size = m0 / static_cast<double>(t.numCells());
  GrowthIntegrator growth(std::make_shared<LinearField>(uniformExpansion(rate, cellCentroid(t, CellId(0)))));
  DivisionScheduler division(SizeThreshold::noisy(1.6 * mean_size, 0.15 * mean_size),
                             makeDivisionRule(rule), DivisionOptions{.seed = 42});
  std::size_t done = 0, skipped = 0;
  const double dt = 0.02;
  int steps = 0;
  while (done < divisions) {
    REQUIRE(++steps < 100000);
    growth.step(t, dt);
    GeometryCache& g = const_cast<GeometryCache&>(growth.geometry());
    const DivisionReport r = division.step(t, g);
    done += r.divided.size();
    skipped += r.skipped.size();
    const ValidationReport v = validate(t);
    INFO("step " << steps << ": " << v.message);
    REQUIRE(v.ok);
    std::set<std::int64_t> ids;
    for (CellId c : t.cells()) ids.insert(t.lineageId(c));
    REQUIRE(ids.size() == t.numCells());
  }
  const double exact = m0 * std::exp(t.dim() * rate * (t.time() - t0));
  CHECK(totalMeasure(t) == Approx(exact).epsilon(2e-3));
  CHECK(skipped <= done / 100);  // degenerate cuts stay rare
}

}  // namespace

TEST_CASE("growth and division of a Voronoi tissue stay valid for every rule", "[growth][long]") {
  const Rectangle domain{Vec3(0, 0, 0), Vec3(4, 3, 0)};
  const Tissue start = voronoiTissue(randomSeeds(domain, 30, 5), domain);
  for (const std::string& rule : divisionRuleNames()) run(start, rule, 0.5, 150);
}

TEST_CASE("growth and division of a box grid stay valid in 3D", "[growth][long]") {
  for (const char* rule : {"main_axis", "shortest_wall", "perpendicular_to_mother_wall", "random"})
    run(boxGrid(2, 2, 2), rule, 0.5, 60);
}

TEST_CASE("thousands of divisions in 2D", "[growth][long][slow]") {
  const Rectangle domain{Vec3(0, 0, 0), Vec3(4, 3, 0)};
  const Tissue start = voronoiTissue(randomSeeds(domain, 30, 6), domain);
  run(start, "shortest_wall", 0.5, 3000);
  run(start, "besson_dumais", 0.5, 3000);
}

TEST_CASE("thousands of divisions in 3D", "[growth][long][slow]") {
  run(boxGrid(2, 2, 2), "shortest_wall", 0.5, 2000);
  run(boxGrid(2, 2, 2), "main_axis", 0.5, 2000);
}
