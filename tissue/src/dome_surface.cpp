// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The dome surface: heights above the footprint and vertical lifts, for the
// dome generator and for growth's projection onto the dome.

#include "tessella/tissue/dome_surface.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella {

void checkDome(const Dome& d) {
  if (!d.base_center.allFinite()) throw InputError("dome.base_center must be finite");
  if (!std::isfinite(d.base_radius) || !(d.base_radius > 0))
    throw InputError("dome.base_radius must be a positive finite number, got " + formatNumber(d.base_radius));
  if (!std::isfinite(d.height) || !(d.height > 0))
    throw InputError("dome.height must be a positive finite number, got " + formatNumber(d.height));
  if (d.shape == Dome::Shape::SphericalCap && d.height > d.base_radius)
    throw InputError("dome.height " + formatNumber(d.height) + " exceeds dome.base_radius " +
                     formatNumber(d.base_radius) +
                     ": a spherical cap taller than a hemisphere is not a height field over its "
                     "footprint");
}

double Dome::heightAt(double r) const {
  checkDome(*this);
  if (!(r >= 0) || r > base_radius * (1 + 1e-12))
    throw InputError("Dome::heightAt: footprint radius " + formatNumber(r) + " is outside [0, " +
                     formatNumber(base_radius) + "]");
  r = std::min(r, base_radius);
  if (shape == Shape::Paraboloid) return height * (1 - (r / base_radius) * (r / base_radius));
  // Sphere through the base circle and the summit: R = (a^2 + h^2) / (2h),
  // centred R - h below the summit. sqrt(R^2 - r^2) - (R - h), written as
  // h - r^2 / (sqrt(R^2 - r^2) + R) to avoid cancellation near the summit.
  const double sphere_radius = (base_radius * base_radius + height * height) / (2 * height);
  return height - r * r / (std::sqrt((sphere_radius - r) * (sphere_radius + r)) + sphere_radius);
}

const EnumTable<Dome::Shape>& domeShapes() {
  static const EnumTable<Dome::Shape> shapes(
      "dome shape", {{"spherical_cap", Dome::Shape::SphericalCap, "A spherical cap (height <= base radius)."},
                     {"paraboloid", Dome::Shape::Paraboloid, "A paraboloid of revolution."}});
  return shapes;
}

Vec3 Dome::lift(const Vec3& p) const {
  const double r = std::hypot(p.x() - base_center.x(), p.y() - base_center.y());
  return Vec3(p.x(), p.y(), base_center.z() + heightAt(r));
}

}  // namespace tessella
