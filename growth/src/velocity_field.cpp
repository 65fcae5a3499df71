// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/velocity_field.hpp"

#include "tessella/growth/parallel_threshold.hpp"

namespace tessella::growth {

void VelocityField::velocities(std::span<const Vec3> x, double t, std::span<Vec3> out) const {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(x.size());
#pragma omp parallel for schedule(static, kInterleavedChunk) if(n >= kParallelMinItems)
  for (std::ptrdiff_t i = 0; i < n; ++i) out[i] = velocity(x[i], t);
}

}  // namespace tessella::growth
