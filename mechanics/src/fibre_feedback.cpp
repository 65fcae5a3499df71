// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/fibre_feedback.hpp"

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

#include <cmath>
#include <numbers>

namespace tessella::mechanics {

void FibreFeedback::check() const {
  if (!(rate >= 0.0 && std::isfinite(rate)))
    throw InputError("mechanics: feedback rate " + formatNumber(rate) + " must be >= 0");
  if (!(noise >= 0.0 && std::isfinite(noise)))
    throw InputError("mechanics: feedback noise " + formatNumber(noise) + " must be >= 0");
}

double axisAngle(const Vec3& fibre, const Vec3& stress_direction, const Vec3& normal) {
  const Vec3 n = normal.normalized();
  const Vec3 f = fibre - fibre.dot(n) * n, s = stress_direction - stress_direction.dot(n) * n;
  double theta = std::atan2(n.dot(s.cross(f)), s.dot(f));
  if (theta > std::numbers::pi / 2) theta -= std::numbers::pi;
  if (theta <= -std::numbers::pi / 2) theta += std::numbers::pi;
  return theta;
}

Vec3 turnFibre(const Vec3& fibre, const Vec3& stress_direction, const Vec3& normal, double rate, double dt,
               double kick) {
  const Vec3 n = normal.normalized();
  const Vec3 s = (stress_direction - stress_direction.dot(n) * n).normalized();
  const double theta = axisAngle(fibre, s, n) * std::exp(-rate * dt) + kick;
  return std::cos(theta) * s + std::sin(theta) * n.cross(s);
}

}  // namespace tessella::mechanics
