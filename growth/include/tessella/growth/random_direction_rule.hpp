// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Random-direction rule: a plane through the centroid with a uniformly random
// orientation (uniform angle in the cell's tangent plane in 2D, uniform
// normal on the sphere in 3D). The null model against which oriented rules
// are compared.

#include "tessella/growth/division_rule.hpp"

namespace tessella::growth {

class RandomDirectionRule final : public DivisionRule {
 public:
  Plane plane(const Tissue& t, CellId c, Rng& rng) const override;
  std::string name() const override { return "random"; }
};

}  // namespace tessella::growth
