// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/shortest_wall_rule.hpp"

#include "tessella/growth/registries.hpp"

namespace tessella::growth {

Plane ShortestWallRule::plane(const Tissue& t, CellId c, Rng&) const {
  const NewWallMeasure m(t, c);
  const std::vector<WallCandidate> minima = newWallLocalMinima(m, options_);
  return m.plane(minima.front().normal);  // the global minimum
}

std::vector<Plane> ShortestWallRule::planes(const Tissue& t, CellId c, Rng&) const {
  const NewWallMeasure m(t, c);
  std::vector<Plane> out;
  for (const WallCandidate& w : newWallLocalMinima(m, options_)) out.push_back(m.plane(w.normal));
  return out;
}

DivisionRuleEntry shortestWallRuleEntry() {
  return {"shortest_wall", "The plane through the centroid that makes the new wall shortest (Errera).", {},
          [](const ParamValues&) { return std::make_shared<const ShortestWallRule>(); }};
}

}  // namespace tessella::growth
