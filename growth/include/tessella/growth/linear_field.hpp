// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Linear growth fields v = G (x - c): G = r I is uniform (isotropic)
// expansion at relative rate r per unit length (areas grow at 2r, volumes
// at 3r); a general G is anisotropic growth, its symmetric part the strain
// rate tensor, its antisymmetric part a rigid rotation rate.

#include "tessella/growth/velocity_field.hpp"

namespace tessella::growth {

class LinearField final : public VelocityField {
 public:
  explicit LinearField(const Mat3& rate, const Vec3& center = Vec3::Zero());
  Vec3 velocity(const Vec3& x, double t) const override;
  void velocities(std::span<const Vec3> x, double t, std::span<Vec3> out) const override;
  std::string describe() const override;
  const Mat3& rate() const { return rate_; }
  const Vec3& center() const { return center_; }

 private:
  Mat3 rate_;
  Vec3 center_;
};

/// v = r (x - c): every length grows as exp(r t).
LinearField uniformExpansion(double rate, const Vec3& center = Vec3::Zero());

/// v = diag(rx, ry, rz) (x - c): growth at different rates along the axes.
LinearField anisotropicGrowth(const Vec3& axis_rates, const Vec3& center = Vec3::Zero());

}  // namespace tessella::growth
