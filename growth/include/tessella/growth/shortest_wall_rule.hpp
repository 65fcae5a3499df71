// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Shortest-wall rule (Errera 1888): the cell divides by the plane through its
// centroid that makes the new wall as short (2D) or as small (3D) as
// possible, found by the minimisation of shortest_wall_search.hpp.

#include "tessella/growth/division_rule.hpp"
#include "tessella/growth/shortest_wall_search.hpp"

namespace tessella::growth {

class ShortestWallRule final : public DivisionRule {
 public:
  explicit ShortestWallRule(ShortestWallSearchOptions options = {}) : options_(options) {}
  Plane plane(const Tissue& t, CellId c, Rng& rng) const override;
  /// Every local minimum of the new wall's measure, smallest first.
  std::vector<Plane> planes(const Tissue& t, CellId c, Rng& rng) const override;
  bool concurrent() const override { return true; }
  std::string name() const override { return "shortest_wall"; }

 private:
  ShortestWallSearchOptions options_;
};

}  // namespace tessella::growth
