// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Stress feedback on fibre directions (docs/mechanics.md, "Stress feedback"):
// cortical microtubules, and the cellulose laid along them, turn toward the
// direction of maximal principal stress. In the plane of a wall (normal n),
// with theta the signed angle from the stress direction s to the fibre f
// (both axes: theta in (-pi/2, pi/2]),
//   d theta / dt = -rate theta  (+ noise: a Brownian kick of sd noise sqrt(dt)),
// integrated exactly over a step: theta <- theta exp(-rate dt) + kick.

#include "tessella/tissue/vec3.hpp"

namespace tessella::mechanics {

struct FibreFeedback {
  double rate = 0.0;   ///< per unit time; 0: off
  double noise = 0.0;  ///< standard deviation of the angle's kick per sqrt(time) (radians)
  void check() const;
};

/// The signed angle from axis s to axis f about n, in (-pi/2, pi/2] (f, s
/// projected on the plane normal to n).
double axisAngle(const Vec3& fibre, const Vec3& stress_direction, const Vec3& normal);
/// The fibre after a step dt: at angle axisAngle(...) exp(-rate dt) + kick
/// from s in the plane normal to n (unit length).
Vec3 turnFibre(const Vec3& fibre, const Vec3& stress_direction, const Vec3& normal, double rate, double dt,
               double kick = 0.0);

}  // namespace tessella::mechanics
