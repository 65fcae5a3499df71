// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Closed triangulated surfaces of revolution about the z axis for the
// membrane tests: a sphere and a capsule (a cylinder with hemispherical
// caps). Triangles are counter-clockwise seen from outside; the two poles are
// points 0 (south) and 1 (north), and ring points follow ring by ring.

#include <array>
#include <cstdint>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::test {

struct SurfaceMesh {
  std::vector<Vec3> points;
  std::vector<std::array<Index, 3>> triangles;
  /// A ring point at angle 0 (on the +x side): its y fixes the rotation about z.
  Index on_x_axis = 0;
};

/// Rings at the meridian points (r_k, z_k) between the poles (0, 0, z_south)
/// and (0, 0, z_north); `around` points per ring, each ring turned half a
/// step from the previous one.
SurfaceMesh revolutionSurface(const std::vector<std::array<double, 2>>& rings, double z_south, double z_north,
                              int around);
/// A sphere of radius R with `rings` rings between the poles.
SurfaceMesh sphereMesh(double R, int rings, int around);
/// A cylinder of radius R and length H (between the caps' bases) with
/// hemispherical caps: `cap_rings` rings on each cap, `length_rings` on the
/// cylinder (both ends included).
SurfaceMesh capsuleMesh(double R, double H, int cap_rings, int length_rings, int around);

/// Supports of a surface of revolution: north pole (vertex 1) fixed, south
/// pole (vertex 0) held in x and y, one ring point held in y: no rigid motion
/// is left and the surface is free to inflate.
inline std::vector<std::uint8_t> supports(const SurfaceMesh& m) {
  std::vector<std::uint8_t> fixed(3 * m.points.size(), 0);
  fixed[3 * 1] = fixed[3 * 1 + 1] = fixed[3 * 1 + 2] = 1;
  fixed[3 * 0] = fixed[3 * 0 + 1] = 1;
  fixed[3 * m.on_x_axis + 1] = 1;
  return fixed;
}

}  // namespace tessella::test
