// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ring.hpp"

#include "tessella/tissue/builders.hpp"

#include <cmath>
#include <numbers>

namespace tessella::test {

Tissue ringTissue(int n, double side) {
  const double radius = side / (2.0 * std::sin(std::numbers::pi / n));
  std::vector<Vec3> points;
  std::vector<Index> loop;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / n;
    points.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0);
    loop.push_back(static_cast<Index>(i));
  }
  return buildPolygonTissue(points, {loop});
}

double ringLoad(int n, double pressure, double stiffness, double rest_length) {
  return pressure * rest_length / (2.0 * stiffness * std::tan(std::numbers::pi / n));
}

double ringSide(int n, double pressure, double stiffness, double rest_length) {
  return rest_length / (1.0 - ringLoad(n, pressure, stiffness, rest_length));
}

}  // namespace tessella::test
