// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "spatial_order.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace tessella::detail {

namespace {

// Cells per axis of the grid the Hilbert index is taken on: 2^13 = 8192, so
// a 26-bit index; points sharing a grid cell keep their index order.
constexpr int kHilbertBits = 13;

// Position of grid cell (x, y) along the Hilbert curve of order kHilbertBits.
// Branch-free: the quadrant's flip and swap are masks, so random points cost
// no mispredictions.
std::uint32_t hilbertIndex(std::uint32_t x, std::uint32_t y) {
  std::uint32_t d = 0;
  for (int b = kHilbertBits - 1; b >= 0; --b) {
    const std::uint32_t s = 1u << b;
    const std::uint32_t rx = (x >> b) & 1u, ry = (y >> b) & 1u;
    d += s * s * ((3 * rx) ^ ry);
    // In the quadrants with ry = 0 the sub-curve is turned: flip (when rx = 1)
    // the bits below b, then swap x and y.
    const std::uint32_t flip = (0u - (rx & (ry ^ 1u))) & (s - 1);
    x ^= flip;
    y ^= flip;
    const std::uint32_t swap = (x ^ y) & (0u - (ry ^ 1u));
    x ^= swap;
    y ^= swap;
  }
  return d;
}

// A well-mixed 64-bit hash (SplitMix64's finaliser).
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace

SpatialOrder2 spatialOrder2(std::span<const Vec3> points) {
  const std::size_t n = points.size();
  SpatialOrder2 out;
  if (n == 0) return out;
  double lo_x = points[0].x(), hi_x = lo_x, lo_y = points[0].y(), hi_y = lo_y;
  for (const Vec3& p : points) {
    lo_x = std::min(lo_x, p.x());
    hi_x = std::max(hi_x, p.x());
    lo_y = std::min(lo_y, p.y());
    hi_y = std::max(hi_y, p.y());
  }
  const double cells = static_cast<double>((1u << kHilbertBits) - 1);
  const double span = std::max({hi_x - lo_x, hi_y - lo_y, 1e-300});
  const double scale = cells / span;
  // Rounds: a point is in the last round with probability 3/4, the one
  // before with 3/16, ...; every round up to the first holds at least ~1000.
  int last_round = 0;
  for (double m = static_cast<double>(n); m > 4000; m /= 4) ++last_round;
  // Sort items: round (6 bits) | Hilbert index (26 bits) | point index.
  std::vector<std::uint64_t> item(n), sorted(n);
  const std::int64_t ns = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < ns; ++i) {
    const auto gx = static_cast<std::uint32_t>((points[i].x() - lo_x) * scale);
    const auto gy = static_cast<std::uint32_t>((points[i].y() - lo_y) * scale);
    const std::uint64_t h = hilbertIndex(std::min<std::uint32_t>(gx, (1u << kHilbertBits) - 1),
                                         std::min<std::uint32_t>(gy, (1u << kHilbertBits) - 1));
    // Level 0 (last round) when u >= 1/4, 1 when 1/16 <= u < 1/4, ...
    const std::uint64_t u = mix(static_cast<std::uint64_t>(i)) >> 1;  // uniform in [0, 2^63)
    int level = 0;
    for (std::uint64_t bound = std::uint64_t(1) << 61; level < last_round && u < bound; bound >>= 2) ++level;
    const auto round = static_cast<std::uint64_t>(last_round - level);
    item[i] = (round << 58) | (h << 32) | static_cast<std::uint64_t>(i);
  }
  // Stable counting sorts (LSD radix): passes over the Hilbert index give
  // the Hilbert order (points sharing a grid cell keep their index order, so
  // the result is unique); one more over the round gives BRIO.
  std::vector<std::uint32_t> start;
  auto countingSort = [&](int shift, int bits) {
    const std::uint64_t mask = (std::uint64_t(1) << bits) - 1;
    start.assign((std::size_t(1) << bits) + 1, 0);
    for (std::uint64_t v : item) ++start[((v >> shift) & mask) + 1];
    for (std::size_t b = 0; b + 1 < start.size(); ++b) start[b + 1] += start[b];
    for (std::uint64_t v : item) sorted[start[(v >> shift) & mask]++] = v;
    item.swap(sorted);
  };
  // Digits of 9 bits: 512 buckets keep the scatter's write streams in cache.
  countingSort(32, 9);
  countingSort(41, 9);
  countingSort(50, 2 * kHilbertBits - 18);
  out.hilbert.resize(n);
  for (std::size_t k = 0; k < n; ++k) out.hilbert[k] = static_cast<Index>(item[k] & 0xffffffffu);
  countingSort(58, 6);
  out.insertion.resize(n);
  for (std::size_t k = 0; k < n; ++k) out.insertion[k] = static_cast<Index>(item[k] & 0xffffffffu);
  return out;
}

}  // namespace tessella::detail
