// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Growth and division sharing one GeometryCache: the division step reads the
// cell measures the growth step computed (nothing is computed twice), and the
// run is bit for bit the run with a private cache per process.

#include <catch2/catch.hpp>

#include <cstring>
#include <memory>

#include "growth_fixtures.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/growth/meristem_field.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::growth;

namespace {

using Q = GeometryQuantity;

bool samePositions(const Tissue& a, const Tissue& b) {
  return a.positions().size() == b.positions().size() &&
         std::memcmp(a.positions().data(), b.positions().data(), a.positions().size() * sizeof(Vec3)) == 0;
}

}  // namespace

TEST_CASE("growth + division with a shared cache: each quantity once per step, the same run as private caches",
          "[growth][geometry]") {
  for (int dim : {2, 3}) {
    INFO("dim " << dim);
    const Tissue start = dim == 2 ? hexagonalGrid(8, 8, 0.5) : boxGrid(4, 4, 3);
    const double mean = totalMeasure(start) / static_cast<double>(start.numCells());
    const auto field = std::make_shared<LinearField>(uniformExpansion(0.2));
    const auto scheduler = [&] {
      return DivisionScheduler(SizeThreshold::noisy(1.1 * mean, 0.1 * mean), makeDivisionRule("main_axis"),
                               DivisionOptions{.seed = 5});
    };
    Tissue shared_tissue = start, private_tissue = start;
    GrowthIntegrator shared_growth(field), private_growth(field);
    DivisionScheduler shared_division = scheduler(), private_division = scheduler();
    GeometryCache shared, division_own;
    std::size_t divisions = 0;
    for (int step = 1; step <= 8; ++step) {
      shared_growth.step(shared_tissue, 0.05, shared);
      const DivisionReport a = shared_division.step(shared_tissue, shared);
      // One computation of each cell measure per step: by the growth step.
      CHECK(shared.computations(Q::FaceMeasures) == static_cast<std::uint64_t>(step));
      CHECK(shared.computations(Q::VolumeMeasures) == static_cast<std::uint64_t>(dim == 3 ? step : 0));
      CHECK(shared.computations(Q::EdgeLengths) == 0);
      CHECK(shared.computations(Q::FaceSecondMoments) == 0);

      private_growth.step(private_tissue, 0.05);
      const DivisionReport b = private_division.step(private_tissue, division_own);
      REQUIRE(a.divided.size() == b.divided.size());
      divisions += a.divided.size();
      REQUIRE(samePositions(shared_tissue, private_tissue));
      for (CellId c : shared_tissue.cells()) REQUIRE(shared_tissue.lineageId(c) == private_tissue.lineageId(c));
    }
    CHECK(divisions > 0);  // the step did divide
    // The private division cache was computed at every step: twice the work.
    CHECK(division_own.computations(Q::FaceMeasures) == 8);
  }
}

TEST_CASE("a surface tissue's normals before the step come from the shared cache", "[growth][geometry]") {
  const double R = 2.0;
  Tissue shared_tissue = testing::sphericalCapGrid(6, 1.2, R);
  Tissue private_tissue = shared_tissue;
  auto field = std::make_shared<MeristemField>(MeristemFieldParams{
      .apex = Vec3(0, 0, R), .central_radius = 0.2, .transition_width = 0.05,
      .central_rate = 0.05, .peripheral_rate = 0.3});
  const GrowthOptions options{.projection = sphereProjection(Vec3::Zero(), R)};
  GrowthIntegrator shared_growth(field, options), private_growth(field, options);
  GeometryCache shared;
  for (int i = 0; i < 5; ++i) {
    shared_growth.step(shared_tissue, 0.1, shared);
    private_growth.step(private_tissue, 0.1);
    REQUIRE(samePositions(shared_tissue, private_tissue));
  }
  // The first step computes the normals before it and the measures after it;
  // every later step finds the normals of its start fresh.
  CHECK(shared.computations(Q::FaceMeasures) == 6);
  CHECK(shared.fresh(shared_tissue, kCellMeasures));
  // A change between steps (another process moving a vertex) is seen.
  shared_tissue.setPosition(VertexId(0), shared_tissue.position(VertexId(0)));
  shared_growth.step(shared_tissue, 0.1, shared);
  CHECK(shared.computations(Q::FaceMeasures) == 8);
}
