// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Main-axis rule: the plane through the centroid perpendicular to the cell's
// longest principal axis (the eigenvector of the largest second moment), so
// elongated cells divide across their length, as in the PlantGL paper's
// MAIN_AXIS algorithm (figure 17).

#include "tessella/growth/division_rule.hpp"

namespace tessella::growth {

class MainAxisRule final : public DivisionRule {
 public:
  Plane plane(const Tissue& t, CellId c, Rng& rng) const override;
  bool concurrent() const override { return true; }
  std::string name() const override { return "main_axis"; }
};

}  // namespace tessella::growth
