// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The bump field of the PlantGL paper (Pradal et al. 2009, section 4.3.1,
// figure 17):
//   v(x, t) = (0, a [1 + b t x^2 / (h + b t)^2] exp(-x^2 / (h + b t)), 0).
// Only y moves, with a speed that depends on x alone, so a vertex keeps its x
// and the exact trajectory is
//   y(t) = y(t0) + a [t exp(-x^2/(h+bt)) - t0 exp(-x^2/(h+bt0))]
// (v_y is the time derivative of a t exp(-x^2/(h+bt))): a Gaussian bump of
// width sqrt(h + b t) centred on x = 0 rising linearly in time.

#include "tessella/growth/velocity_field.hpp"

namespace tessella::growth {

struct BumpFieldParams {
  double a = 1.0;  ///< amplitude (speed at x = 0)
  double b = 1.0;  ///< widening rate of the bump
  double h = 1.0;  ///< initial squared width of the bump (> 0)
  /// x is measured from this abscissa (the paper's bump is centred on 0).
  double x0 = 0.0;
};

class BumpField final : public VelocityField {
 public:
  /// Throws InputError when h + b t could reach zero for t >= 0 (h <= 0 or
  /// b < 0 makes the width vanish) or a parameter is not finite.
  explicit BumpField(const BumpFieldParams& params);
  Vec3 velocity(const Vec3& x, double t) const override;
  std::string describe() const override;
  /// The exact y displacement of a point at abscissa x between t0 and t1.
  double displacement(double x, double t0, double t1) const;

 private:
  BumpFieldParams p_;
};

}  // namespace tessella::growth
