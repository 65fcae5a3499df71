// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/division_scheduler.hpp"

#include <cmath>
#include <Eigen/Geometry>

#include "tessella/growth/cell_frame.hpp"
#include "tessella/growth/division_walls.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::growth {

namespace {
// Which daughter gets the new lineage id must not hang on the sign an
// eigen-solver happens to give an axis (round-off can flip it, e.g. after a
// restart): the new cell is always on the side the normal's largest
// component points to (+x for a vertical wall, +y for a horizontal one).
Plane withCanonicalSide(Plane plane) {
  Eigen::Index largest = 0;
  plane.normal.cwiseAbs().maxCoeff(&largest);
  if (plane.normal[largest] < 0) plane.normal = -plane.normal;
  return plane;
}
}  // namespace

DivisionScheduler::DivisionScheduler(SizeThreshold trigger, std::shared_ptr<const DivisionRule> rule,
                                     DivisionOptions options)
    : trigger_(std::move(trigger)), rule_(std::move(rule)), options_(options), rng_(options.seed) {
  if (!rule_) throw InputError("division scheduler: no division rule");
  if (options_.max_attempts < 1)
    throw InputError("division scheduler: max_attempts = " + std::to_string(options_.max_attempts) +
                     " must be >= 1");
}

DivisionRecord DivisionScheduler::divide(Tissue& t, CellId c, Rng& rng) {
  if (options_.tag_walls) divisionWallTags(t);
  const std::int64_t mother = t.lineageId(c);
  const Plane base = withCanonicalSide(rule_->plane(t, c, rng));
  // Perturbations for degenerate cuts: rotate about the cell normal (2D) or
  // an axis perpendicular to the plane normal (3D), and shift along it.
  const Vec3 n0 = base.normal.normalized();
  const Vec3 axis = t.dim() == 2 ? cellFrame(t, c).normal : n0.unitOrthogonal();
  const double size = t.dim() == 2 ? std::sqrt(std::abs(cellMeasure(t, c)))
                                   : std::cbrt(std::abs(cellMeasure(t, c)));
  std::string last_error;
  for (int attempt = 0; attempt < options_.max_attempts; ++attempt) {
    Plane p = base;
    if (attempt > 0) {
      const int k = (attempt + 1) / 2;
      const double sign = attempt % 2 == 1 ? 1.0 : -1.0;
      p.normal = Eigen::AngleAxisd(sign * k * options_.retry_angle, axis) * n0;
      p.point = base.point + sign * k * options_.retry_shift * size * n0;
    }
    try {
      const CellSplit split = t.splitCell(c, p, options_.split);
      if (options_.tag_walls) divisionWallTags(t)[split.wall] = mother;
      return DivisionRecord{mother, c, split.daughter, split.wall, attempt + 1};
    } catch (const GeometryError& e) {
      last_error = e.what();
    }
  }
  throw GeometryError("cell " + std::to_string(c.index()) + " (lineage id " +
                          std::to_string(mother) + ") could not be divided by rule '" +
                          rule_->name() + "' in " + std::to_string(options_.max_attempts) +
                          " attempts: " + last_error,
                      ElementId{t.dim(), c.index()});
}

DivisionReport DivisionScheduler::step(Tissue& t, GeometryCache& geometry, Rng& rng) {
  DivisionReport report;
  const std::vector<CellId> due = trigger_.cellsDue(t, geometry.require(t, kCellMeasures), rng);
  for (CellId c : due) {
    if (options_.gate && !options_.gate(t, c)) continue;
    try {
      report.divided.push_back(divide(t, c, rng));
    } catch (const GeometryError& e) {
      report.skipped.push_back(SkippedDivision{c, t.lineageId(c), e.what()});
    }
  }
  // New cells (daughters) draw their noisy thresholds now, so they are set
  // before any caller reads them.
  if (!report.divided.empty()) trigger_.prepare(t, rng);
  return report;
}

}  // namespace tessella::growth
