// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The dome surface: a spherical cap or a paraboloid of revolution over a
// footprint disk. Tissue vocabulary shared by the dome generator (which puts
// a sheet's vertices on it, generators/dome.hpp) and growth (which keeps them
// there, growth::domeProjection), so neither has to know the other.

#include "tessella/tissue/enum_table.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella {

/// The surface a dome tissue lies on. Only vertices lie on it: a dome
/// tissue's walls are straight chords and its cells slightly non-planar
/// polygons.
struct Dome {
  enum class Shape { SphericalCap, Paraboloid };
  Shape shape = Shape::SphericalCap;
  double base_radius = 1.0;  ///< radius of the footprint disk
  double height = 0.5;       ///< height of the summit above the base plane
  Vec3 base_center = Vec3::Zero();
  /// Height of the surface above the base plane at footprint radius r in
  /// [0, base_radius]: the sphere through the base circle and the summit
  /// (needs height <= base_radius), or height * (1 - r^2 / base_radius^2).
  /// InputError for r outside the footprint or invalid dome fields.
  double heightAt(double r) const;
  /// Projects a point vertically onto the surface.
  Vec3 lift(const Vec3& p) const;
};

/// InputError naming the field when a dome's fields are not finite, its
/// radius or height not positive, or a spherical cap is taller than a
/// hemisphere (no longer a height field over its footprint).
void checkDome(const Dome& dome);

/// The shapes' names in configurations, scripts and saved run states:
/// spherical_cap, paraboloid.
const EnumTable<Dome::Shape>& domeShapes();

}  // namespace tessella
