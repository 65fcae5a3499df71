// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "surface_meshes.hpp"

#include <cmath>
#include <numbers>

namespace tessella::test {

SurfaceMesh revolutionSurface(const std::vector<std::array<double, 2>>& rings, double z_south, double z_north,
                              int around) {
  SurfaceMesh m;
  m.points.emplace_back(0, 0, z_south);
  m.points.emplace_back(0, 0, z_north);
  const int n = around;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const double shift = 0.5 * static_cast<double>(k % 2);  // staggered rings: no shared diagonal direction
    for (int j = 0; j < n; ++j) {
      const double angle = 2.0 * std::numbers::pi * (j + shift) / n;
      m.points.emplace_back(rings[k][0] * std::cos(angle), rings[k][0] * std::sin(angle), rings[k][1]);
    }
  }
  m.on_x_axis = 2;  // ring 0, j = 0 (unshifted)
  auto ring = [&](std::size_t k, int j) {
    return static_cast<Index>(2 + k * n + static_cast<std::size_t>((j + n) % n));
  };
  for (int j = 0; j < n; ++j) m.triangles.push_back({0, ring(0, j + 1), ring(0, j)});
  for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
    // Ring k+1 is turned by +half a step (k even) or -half a step (k odd) relative to ring k.
    for (int j = 0; j < n; ++j) {
      if (k % 2 == 0) {
        m.triangles.push_back({ring(k, j), ring(k, j + 1), ring(k + 1, j)});
        m.triangles.push_back({ring(k, j + 1), ring(k + 1, j + 1), ring(k + 1, j)});
      } else {
        m.triangles.push_back({ring(k, j), ring(k + 1, j + 1), ring(k + 1, j)});
        m.triangles.push_back({ring(k, j), ring(k, j + 1), ring(k + 1, j + 1)});
      }
    }
  }
  const std::size_t last = rings.size() - 1;
  for (int j = 0; j < n; ++j) m.triangles.push_back({1, ring(last, j), ring(last, j + 1)});
  return m;
}

SurfaceMesh sphereMesh(double R, int rings, int around) {
  std::vector<std::array<double, 2>> profile;
  for (int k = 1; k <= rings; ++k) {
    const double theta = std::numbers::pi * k / (rings + 1);
    profile.push_back({R * std::sin(theta), -R * std::cos(theta)});
  }
  return revolutionSurface(profile, -R, R, around);
}

SurfaceMesh capsuleMesh(double R, double H, int cap_rings, int length_rings, int around) {
  std::vector<std::array<double, 2>> profile;
  for (int k = 1; k <= cap_rings; ++k) {  // south cap, up to its equator (excluded)
    const double theta = 0.5 * std::numbers::pi * k / (cap_rings + 1);
    profile.push_back({R * std::sin(theta), -0.5 * H - R * std::cos(theta)});
  }
  for (int k = 0; k < length_rings; ++k) profile.push_back({R, -0.5 * H + H * k / (length_rings - 1)});
  for (int k = cap_rings; k >= 1; --k) {
    const double theta = 0.5 * std::numbers::pi * k / (cap_rings + 1);
    profile.push_back({R * std::sin(theta), 0.5 * H + R * std::cos(theta)});
  }
  return revolutionSurface(profile, -0.5 * H - R, 0.5 * H + R, around);
}

}  // namespace tessella::test
