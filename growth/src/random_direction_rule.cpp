// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/random_direction_rule.hpp"

#include <numbers>

#include "tessella/growth/cell_frame.hpp"
#include "tessella/growth/registries.hpp"

namespace tessella::growth {

Plane RandomDirectionRule::plane(const Tissue& t, CellId c, Rng& rng) const {
  const CellFrame f = cellFrame(t, c);
  if (t.dim() == 2) {
    const double theta = std::uniform_real_distribution<double>(0.0, std::numbers::pi)(rng);
    return Plane{f.centroid, f.direction(theta)};
  }
  // A normalised Gaussian vector is uniform on the sphere.
  std::normal_distribution<double> g;
  Vec3 n;
  do n = Vec3(g(rng), g(rng), g(rng));
  while (n.norm() < 1e-12);
  return Plane{f.centroid, n.normalized()};
}

DivisionRuleEntry randomDirectionRuleEntry() {
  return {"random", "A random direction through the centroid (uniform in the tangent plane, or on the sphere in 3D).",
          {}, [](const ParamValues&) { return std::make_shared<const RandomDirectionRule>(); }};
}

}  // namespace tessella::growth
