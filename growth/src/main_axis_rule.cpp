// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/main_axis_rule.hpp"

#include "tessella/growth/cell_frame.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::growth {

Plane MainAxisRule::plane(const Tissue& t, CellId c, Rng&) const {
  const PrincipalAxes axes = cellPrincipalAxes(t, c);
  return planeThroughCentroid(t, c, axes.axes.col(0), "main_axis rule");
}

DivisionRuleEntry mainAxisRuleEntry() {
  return {"main_axis",
          "Across the cell's longest principal axis, through its centroid (the PlantGL MAIN_AXIS of figure 17).",
          {},
          [](const ParamValues&) { return std::make_shared<const MainAxisRule>(); }};
}

}  // namespace tessella::growth
