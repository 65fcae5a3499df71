// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "interior_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "closest_point.hpp"

namespace tessella::mesh::detail {

double windingNumber(const std::vector<Triangle>& outward, const Vec3& p) {
  double total = 0.0;
  for (const Triangle& t : outward) {
    const Vec3 a = t[0] - p, b = t[1] - p, c = t[2] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(num, den);
  }
  return total / (4.0 * std::numbers::pi);
}

double distanceToSurface(const std::vector<Triangle>& triangles, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Triangle& t : triangles) best = std::min(best, (closestPointOnTriangle(p, t[0], t[1], t[2]) - p).norm());
  return best;
}

std::optional<Vec3> interiorPoint(const std::vector<Triangle>& outward, const Vec3& guess, double min_clearance) {
  const auto inside = [&](const Vec3& p) { return std::abs(windingNumber(outward, p) - 1.0) < 0.25; };
  if (inside(guess) && distanceToSurface(outward, guess) >= min_clearance) return guess;
  std::optional<Vec3> best;
  double best_clearance = min_clearance;
  for (const Triangle& t : outward) {
    const Vec3 cross = (t[1] - t[0]).cross(t[2] - t[0]);
    const double area2 = cross.norm();
    if (!(area2 > 0.0)) continue;
    const double perimeter = (t[1] - t[0]).norm() + (t[2] - t[1]).norm() + (t[0] - t[2]).norm();
    const double inradius = area2 / perimeter;
    const Vec3 inward = -cross / area2;
    const Vec3 centre = (t[0] + t[1] + t[2]) / 3.0;
    for (double fraction : {1.0, 0.3, 0.1}) {
      const Vec3 q = centre + fraction * inradius * inward;
      const double clearance = distanceToSurface(outward, q);
      if (clearance >= best_clearance && inside(q)) {
        best = q;
        best_clearance = clearance;
      }
    }
  }
  return best;
}

}  // namespace tessella::mesh::detail
