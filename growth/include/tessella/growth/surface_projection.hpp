// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Surface projections keep a curved-sheet tissue (the L1 layer of a dome) on
// its surface while it grows: the integrator applies one to every vertex
// after every stage. A projection maps a point to the nearest point (or, for
// lift(), the point vertically above/below) on the surface.

#include <functional>

#include "tessella/tissue/dome_surface.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::growth {

using SurfaceProjection = std::function<Vec3(const Vec3&)>;

/// Nearest point on the sphere |x - center| = radius (radial projection).
/// Throws InputError for a non-positive radius.
SurfaceProjection sphereProjection(const Vec3& center, double radius);

/// Nearest point on the paraboloid of revolution z = apex.z - curvature * rho^2
/// (rho the distance from the vertical axis through apex): a dome opening
/// downwards for curvature > 0. Solved by Newton's method on the meridian.
/// Throws InputError for a non-positive curvature.
SurfaceProjection paraboloidProjection(const Vec3& apex, double curvature);

/// Nearest-point projection onto a dome surface (tissue/dome_surface.hpp; the
/// one the dome generator puts the vertices on), extended past the dome's
/// base so cells can flow down the flanks: the whole sphere of a spherical
/// cap, the whole paraboloid of a paraboloid dome.
SurfaceProjection domeProjection(const Dome& dome);

}  // namespace tessella::growth
