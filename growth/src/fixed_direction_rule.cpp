#include "tessella/growth/fixed_direction_rule.hpp"

#include "tessella/growth/cell_frame.hpp"
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

}  // namespace tessella::growth
