// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The tangent frame of a 2D cell (planar or on a curved sheet): centroid,
// unit normal and two unit tangents. Division planes of 2D cells are spanned
// by the normal and one tangent direction, so they cut the cell along a line
// in its tangent plane. In 3D the frame is the centroid with the world axes.

#include "tessella/tissue/tissue.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::growth {

struct CellFrame {
  Vec3 centroid = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  Vec3 e1 = Vec3::UnitX();
  Vec3 e2 = Vec3::UnitY();
  /// The in-plane unit direction at angle theta from e1 (2D cells).
  Vec3 direction(double theta) const;
};

/// Planar tissues use +z as the normal (exactly), surfaces the polygon's mean
/// normal. Throws GeometryError naming the cell when it has no area.
CellFrame cellFrame(const Tissue& t, CellId c);

/// The plane through the cell's centroid whose normal is `direction` made
/// tangent to a 2D cell (its component along the cell normal removed) or
/// taken as is in 3D. Throws GeometryError naming the cell (and `rule`) when
/// nothing is left of the direction.
Plane planeThroughCentroid(const Tissue& t, CellId c, const Vec3& direction, const char* rule);

}  // namespace tessella::growth
