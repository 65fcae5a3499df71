// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A dome of 24 jittered seeds (a 4 x 3 x 2 grid) in 48 x 40 x 24 voxels of
// 0.5 x 0.5 x 1, each voxel labelled by its nearest seed (label 2 + seed),
// background (0) above the half ellipsoid of radii 24, 20, 23 voxels on the
// base: cells of 60 to 1900 voxels, some a voxel or two thick where the dome
// cuts them, with curved walls. The jitter (+-2 voxels per coordinate) comes
// from splitmix64, so the image is the same on every platform. tests/io
// imports it (test_label_image_3d.cpp); tests/sim grows, divides and meshes it
// (test_divided_dome.cpp).

#include <cmath>
#include <cstdint>
#include <vector>

#include "tessella/io/label_image.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::io::testing {

inline LabelImage domeImage(std::uint64_t seed) {
  constexpr std::int64_t nx = 48, ny = 40, nz = 24;
  auto next = [&seed] {
    seed += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = seed;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  };
  std::vector<Vec3> seeds;
  for (int gz = 0; gz < 2; ++gz)
    for (int gy = 0; gy < 3; ++gy)
      for (int gx = 0; gx < 4; ++gx) {
        Vec3 p((gx + 0.5) * nx / 4.0, (gy + 0.5) * ny / 3.0, (gz + 0.5) * (nz - 2) / 2.0);
        for (int a = 0; a < 3; ++a) p[a] += -2.0 + 4.0 * next();
        seeds.push_back(p);
      }
  LabelImage img;
  img.name = "dome";
  img.dims = {nx, ny, nz};
  img.spacing = {0.5, 0.5, 1.0};
  for (std::int64_t k = 0; k < nz; ++k)
    for (std::int64_t j = 0; j < ny; ++j)
      for (std::int64_t i = 0; i < nx; ++i) {
        const Vec3 p(i + 0.5, j + 0.5, k + 0.5);
        const double r = std::pow((p.x() - nx / 2.0) / 24, 2) +
                         std::pow((p.y() - ny / 2.0) / 20, 2) + std::pow(p.z() / 23, 2);
        std::size_t nearest = 0;
        for (std::size_t s = 1; s < seeds.size(); ++s)
          if ((seeds[s] - p).squaredNorm() < (seeds[nearest] - p).squaredNorm()) nearest = s;
        img.labels.push_back(r <= 1 ? static_cast<std::int64_t>(nearest) + 2 : 0);
      }
  return img;
}

}  // namespace tessella::io::testing
