// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Radial growth: every point moves straight away from a centre (or, when an
// axis is given, from an axis) with speed rate * d^exponent, d the distance.
// exponent 1 is uniform expansion (of the plane perpendicular to the axis
// when there is one); exponent 0 a constant outward speed; exponent > 1
// concentrates growth at the rim.

#include "tessella/growth/velocity_field.hpp"

namespace tessella::growth {

struct RadialFieldParams {
  Vec3 center = Vec3::Zero();
  /// Zero: spherical growth from `center`. Non-zero: cylindrical growth away
  /// from the line through `center` along this axis (a disk grows in its plane).
  Vec3 axis = Vec3::Zero();
  double rate = 1.0;
  double exponent = 1.0;
};

class RadialField final : public VelocityField {
 public:
  /// Throws InputError for a negative exponent or a non-finite parameter.
  explicit RadialField(const RadialFieldParams& params);
  Vec3 velocity(const Vec3& x, double t) const override;
  std::string describe() const override;

 private:
  RadialFieldParams p_;
};

}  // namespace tessella::growth
