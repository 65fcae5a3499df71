// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Fixed-direction rule: a plane through the centroid with a given normal, so
// every new wall is perpendicular to one direction (e.g. transverse walls of
// a file of cells). On a surface tissue the normal is made tangent to each
// cell; a cell whose normal is parallel to the direction cannot be cut
// (GeometryError naming the cell).

#include "tessella/growth/division_rule.hpp"

namespace tessella::growth {

class FixedDirectionRule final : public DivisionRule {
 public:
  /// InputError for a zero or non-finite normal.
  explicit FixedDirectionRule(const Vec3& normal);
  Plane plane(const Tissue& t, CellId c, Rng& rng) const override;
  bool concurrent() const override { return true; }
  std::string name() const override { return "fixed"; }
  const Vec3& normal() const { return normal_; }

 private:
  Vec3 normal_;
};

}  // namespace tessella::growth
