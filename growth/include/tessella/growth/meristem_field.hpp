// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Shoot apical meristem growth on a dome: a slowly growing central zone
// around the summit and a fast peripheral zone (Reddy et al. 2004; Kwiatkowska
// 2004). Points move away from the summit,
//   v = k(rho) (x - apex),   k(rho) = k_c + (k_p - k_c) s((rho - R) / w),
// rho the distance from the dome axis, R the central-zone radius, w the width
// of the transition and s(u) = (1 + tanh u) / 2 a smooth step. Used with a
// surface projection onto the dome, cells flow from the summit down the
// flanks while the dome keeps its shape (the meristem's steady state).

#include "tessella/growth/velocity_field.hpp"

namespace tessella::growth {

struct MeristemFieldParams {
  Vec3 apex = Vec3(0, 0, 0);   ///< summit of the dome
  Vec3 axis = Vec3::UnitZ();   ///< dome axis (towards the summit's outside)
  double central_radius = 0.3; ///< R: radius of the central zone
  double transition_width = 0.05; ///< w (> 0)
  double central_rate = 0.02;  ///< k_c: relative rate inside the central zone
  double peripheral_rate = 0.1; ///< k_p: relative rate in the peripheral zone
};

class MeristemField final : public VelocityField {
 public:
  /// Throws InputError for a zero axis, a non-positive radius or width.
  explicit MeristemField(const MeristemFieldParams& params);
  Vec3 velocity(const Vec3& x, double t) const override;
  std::string describe() const override;
  /// k(rho): the relative rate at distance rho from the axis.
  double rateAt(double rho) const;

 private:
  MeristemFieldParams p_;
};

}  // namespace tessella::growth
