// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/fixed_direction_rule.hpp"

#include "tessella/growth/cell_frame.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::growth {

FixedDirectionRule::FixedDirectionRule(const Vec3& normal) : normal_(normal) {
  if (!normal_.allFinite() || normal_.norm() == 0)
    throw InputError("fixed division rule: the normal must be finite and non-zero");
  normal_.normalize();
}

Plane FixedDirectionRule::plane(const Tissue& t, CellId c, Rng&) const {
  return planeThroughCentroid(t, c, normal_, "fixed division rule");
}

DivisionRuleEntry fixedDirectionRuleEntry() {
  return {"fixed", "A fixed direction: every plane has the normal `fixed_normal` (made tangent on curved sheets).",
          {ParamSpec("fixed_normal", ParamType::Vec3, "Normal of every division plane (rule: fixed).")
               .byDefault(std::vector<double>{1, 0, 0})},
          [](const ParamValues& p) {
            return blameParam("fixed_normal",
                              [&] { return std::make_shared<const FixedDirectionRule>(p.getVec3("fixed_normal")); });
          }};
}

}  // namespace tessella::growth
