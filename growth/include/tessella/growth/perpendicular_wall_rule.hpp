// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Hofmeister/Sachs rule (Hofmeister 1863; Sachs 1878): the new wall meets the
// wall through which the cell was born (its mother's division wall, see
// division_walls.hpp) at right angles.
//   2D / surface: the plane's normal is the birth wall's direction (the
//   chord of its pieces), made tangent to the cell.
//   3D: the plane contains the birth wall's normal; among those planes, the
//   one whose normal is closest to the cell's main axis.
// The plane passes through the centroid, shifted along its normal when it
// would pass within `junction_tolerance` (relative to the cell size,
// sqrt(area) or cbrt(volume)) of a vertex of the birth wall: the new wall
// would meet an existing junction there (typically the sister's division
// wall) and make a four-way junction, which plant cells avoid.
// Cells with no birth wall (founders) use the fallback rule.

#include <memory>

#include "tessella/growth/division_rule.hpp"

namespace tessella::growth {

class PerpendicularWallRule final : public DivisionRule {
 public:
  /// fallback: the rule for founder cells (main axis when null).
  explicit PerpendicularWallRule(double junction_tolerance = 0.05,
                                 std::shared_ptr<const DivisionRule> fallback = nullptr);
  Plane plane(const Tissue& t, CellId c, Rng& rng) const override;
  bool concurrent() const override;
  std::string name() const override { return "perpendicular_to_mother_wall"; }

 private:
  double junction_tolerance_;
  std::shared_ptr<const DivisionRule> fallback_;
};

}  // namespace tessella::growth
