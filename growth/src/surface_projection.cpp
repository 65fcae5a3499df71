// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/surface_projection.hpp"

#include <cmath>
#include <string>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::growth {

SurfaceProjection sphereProjection(const Vec3& center, double radius) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw InputError("sphere projection: radius = " + formatNumber(radius) + " must be > 0");
  return [center, radius](const Vec3& p) -> Vec3 {
    const Vec3 d = p - center;
    const double n = d.norm();
    if (n == 0) return center + radius * Vec3::UnitZ();  // any point is nearest; take the pole
    return center + (radius / n) * d;
  };
}

SurfaceProjection paraboloidProjection(const Vec3& apex, double curvature) {
  if (!(curvature > 0) || !std::isfinite(curvature))
    throw InputError("paraboloid projection: curvature = " + formatNumber(curvature) +
                     " must be > 0");
  return [apex, curvature](const Vec3& p) -> Vec3 {
    // Work in the meridian plane: point (r0, z0) relative to the apex, surface
    // z = -k r^2. The nearest point r minimises (r - r0)^2 + (-k r^2 - z0)^2:
    // g(r) = r - r0 + 2 k r (k r^2 + z0) = 0, a cubic with g' = 1 + 2k z0 + 6k^2 r^2.
    const Vec3 d = p - apex;
    const double r0 = std::hypot(d.x(), d.y()), z0 = d.z(), k = curvature;
    double r = r0;  // start from the vertical projection
    for (int it = 0; it < 50; ++it) {
      const double g = r - r0 + 2 * k * r * (k * r * r + z0);
      double dg = 1 + 2 * k * z0 + 6 * k * k * r * r;
      if (dg <= 1e-12) dg = 1e-12;  // far above the focus: the cubic may have 3 roots; stay monotone
      const double step = g / dg;
      r -= step;
      if (r < 0) r = 0;
      if (std::abs(step) <= 1e-15 * (1 + std::abs(r))) break;
    }
    Vec3 out = apex;
    if (r0 > 0) {
      out.x() += d.x() * (r / r0);
      out.y() += d.y() * (r / r0);
    }
    out.z() += -k * r * r;
    return out;
  };
}

SurfaceProjection domeProjection(const Dome& dome) {
  const double r = dome.base_radius, h = dome.height;
  if (!(r > 0) || !(h > 0))
    throw InputError("dome projection: base_radius and height must be > 0");
  const Vec3 summit = dome.base_center + Vec3(0, 0, h);
  if (dome.shape == Dome::Shape::Paraboloid)
    return paraboloidProjection(summit, h / (r * r));  // z = h (1 - rho^2 / r^2)
  // The cap's sphere passes through the summit and the base circle.
  const double radius = (r * r + h * h) / (2 * h);
  return sphereProjection(summit - Vec3(0, 0, radius), radius);
}

}  // namespace tessella::growth
