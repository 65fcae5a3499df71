// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: a point strictly inside a closed triangulated surface (a 3D cell),
// with clearance from its walls, for TetGen's region seeds. Also for
// non-convex cells, whose centroid may lie outside.

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "tessella/tissue/vec3.hpp"

namespace tessella::mesh::detail {

using Triangle = std::array<Vec3, 3>;

/// Generalised winding number of a closed surface of outward triangles
/// around p: 1 inside, 0 outside (solid angles, Van Oosterom & Strackee).
double windingNumber(const std::vector<Triangle>& outward, const Vec3& p);

/// Distance from p to the nearest triangle.
double distanceToSurface(const std::vector<Triangle>& triangles, const Vec3& p);

/// A point with winding number 1 and clearance at least min_clearance:
/// the guess (normally the centroid) when it qualifies, else the best of
/// points just inside each triangle (offset along its inward normal by a
/// few fractions of its inradius). nullopt if none qualifies.
std::optional<Vec3> interiorPoint(const std::vector<Triangle>& outward, const Vec3& guess, double min_clearance);

}  // namespace tessella::mesh::detail
