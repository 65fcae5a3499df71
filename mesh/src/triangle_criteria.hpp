// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: MeshOptions -> CGAL's Delaunay_mesh_criteria_2 shape bound.

#include <cmath>
#include <numbers>

namespace tessella::mesh::detail {

/// CGAL bounds B = sin^2(smallest angle): a triangle is bad when the sine of
/// its smallest angle, squared, is below B.
inline double shapeBound(double min_angle_degrees) {
  const double s = std::sin(min_angle_degrees * std::numbers::pi / 180.0);
  return s * s;
}

}  // namespace tessella::mesh::detail
