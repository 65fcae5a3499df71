// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// An imported tissue of thin, curved cells (the dome label image of tests/io)
// divided by the shortest wall must still mesh (issue #15): a division whose
// walls would cross another wall is refused (growth/division_crossings.hpp)
// and the rule's next plane taken. The refusal is checked against the
// mesher's own geometry check of the divided tissue.

#include <string>

#include <catch2/catch.hpp>

#include "../io/dome_label_image.hpp"
#include "tessella/growth/division_crossings.hpp"
#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/shortest_wall_rule.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/label_image.hpp"
#include "tessella/mesh/geometry_check.hpp"
#include "tessella/tissue/cell_split_plan.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using Catch::Matchers::Contains;

namespace {

// As configs/from_label_image_3d.yaml imports its image.
Tissue importedDome() {
  io::ImportOptions o;
  o.image.min_cell_size = 50;
  o.image.small_cells = "merge";
  o.simplify = 0;
  Tissue t = io::tissueFromLabelImage(io::testing::domeImage(1), o).tissue;
  REQUIRE(validate(t).ok);
  REQUIRE(mesh::findGeometryDefects(t).ok);
  return t;
}

// A rule with one given plane.
class GivenPlane final : public growth::DivisionRule {
 public:
  explicit GivenPlane(Plane p) : p_(p) {}
  Plane plane(const Tissue&, CellId, growth::Rng&) const override { return p_; }
  std::string name() const override { return "given"; }

 private:
  Plane p_;
};

}  // namespace

TEST_CASE("a division plane is refused exactly when the divided tissue would not mesh",
          "[sim][division]") {
  // Every cell of the imported dome, by its shortest-wall plane: the refusal (walls that would
  // cross, tested on the planned walls alone) against the mesher's check of the whole tissue
  // divided by that plane.
  const Tissue dome = importedDome();
  const growth::ShortestWallRule rule;
  growth::Rng rng(1);
  int refused = 0, planned = 0;
  for (CellId c : dome.cells()) {
    const Plane p = rule.plane(dome, c, rng);
    CellSplitPlan3D plan;
    try {
      plan = planCellSplit3D(dome, c, p);
    } catch (const GeometryError&) {
      continue;
    }
    ++planned;
    const std::string crossing = growth::divisionCrossing(dome, c, plan);
    Tissue divided = dome;
    divided.splitCell(c, p);
    const mesh::MeshabilityReport meshable = mesh::findGeometryDefects(divided);
    INFO("cell " << c.index() << ": refusal '" << crossing << "', mesher '" << meshable.message
                 << "'");
    CHECK(crossing.empty() == meshable.ok);
    if (!crossing.empty()) {
      ++refused;
      CHECK_THAT(crossing, Contains("dividing cell " + std::to_string(c.index()) + " (lineage "));
    }
  }
  CHECK(planned >= 12);  // most cells (the others: planes splitCell refuses, a degenerate cut)
  CHECK(refused >=
        1);  // main at 6427d27 divided cells 8 and 22 so (the mesher then refused the tissue)
}

TEST_CASE("the dome divided three times by the shortest wall meshes after every round",
          "[sim][division]") {
  Tissue t = importedDome();
  growth::DivisionScheduler divide(growth::SizeThreshold::fixed(1.0),
                                   std::make_shared<growth::ShortestWallRule>());
  GeometryCache geometry;
  int later_planes = 0;
  for (int round = 1; round <= 3; ++round) {
    INFO("round " << round);
    const std::size_t before = t.numCells();
    const growth::DivisionReport r = divide.step(t, geometry);
    geometry = GeometryCache{};
    // Every cell is over the threshold: each divides or is reported with its reason.
    CHECK(r.divided.size() + r.skipped.size() == before);
    CHECK(t.numCells() == before + r.divided.size());
    for (const auto& s : r.skipped)
      CHECK_THAT(s.reason, Contains("cell " + std::to_string(s.cell.index())));
    for (const auto& d : r.divided)
      later_planes += d.attempts > 5;  // past the first plane's 5 attempts
    const auto valid = validate(t);
    INFO(valid.message);
    REQUIRE(valid.ok);
    const mesh::MeshabilityReport meshable = mesh::findGeometryDefects(t);
    INFO(meshable.message);
    CHECK(meshable.ok);
  }
  CHECK(t.numCells() >= 150);
  CHECK(later_planes >= 1);  // some cells took the rule's second (or later) plane
}

TEST_CASE("a cell whose only plane would make walls cross is skipped with the reason",
          "[sim][division]") {
  // The first cell whose shortest-wall plane is refused, given to a rule with that plane alone.
  const Tissue dome = importedDome();
  const growth::ShortestWallRule rule;
  growth::Rng rng(1);
  for (CellId c : dome.cells()) {
    const Plane p = rule.plane(dome, c, rng);
    try {
      if (growth::divisionCrossing(dome, c, planCellSplit3D(dome, c, p)).empty()) continue;
    } catch (const GeometryError&) {
      continue;
    }
    growth::DivisionOptions o;
    o.max_attempts = 1;
    growth::DivisionScheduler s(growth::SizeThreshold::fixed(1.0), std::make_shared<GivenPlane>(p),
                                o);
    Tissue t = dome;
    const std::string cell = "cell " + std::to_string(c.index()) + " (lineage id " +
                             std::to_string(t.lineageId(c)) + ")";
    std::string message;
    try {
      s.divide(t, c);
    } catch (const GeometryError& e) {
      message = e.what();
    }
    CHECK_THAT(message, Contains(cell + " could not be divided by rule 'given' in 1 attempts") &&
                            Contains("by this plane would make") && Contains("cross"));
    CHECK(t.numCells() == dome.numCells());  // nothing changed
    return;
  }
  FAIL("no cell of the dome has a refused shortest-wall plane");
}
