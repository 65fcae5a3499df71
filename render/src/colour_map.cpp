// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/render/colour_map.hpp"

#include <algorithm>
#include <cmath>

namespace tessella::render {

namespace {
// matplotlib's viridis at t = 0, 1/8, ..., 1 (8-bit values of its table);
// linear interpolation between them stays within 2/255 of the full table.
constexpr std::array<std::array<double, 3>, 9> kViridis = {{{68, 1, 84},
                                                            {71, 44, 122},
                                                            {59, 81, 139},
                                                            {44, 113, 142},
                                                            {33, 144, 141},
                                                            {39, 173, 129},
                                                            {92, 200, 99},
                                                            {170, 220, 50},
                                                            {253, 231, 37}}};
}  // namespace

Rgb viridis(double t) {
  if (std::isnan(t)) return {0.6, 0.6, 0.6};
  t = std::clamp(t, 0.0, 1.0) * (kViridis.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(t), kViridis.size() - 2);
  const double f = t - static_cast<double>(i);
  Rgb out{};
  for (int k = 0; k < 3; ++k) out[k] = ((1 - f) * kViridis[i][k] + f * kViridis[i + 1][k]) / 255.0;
  return out;
}

}  // namespace tessella::render
