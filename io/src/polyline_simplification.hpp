// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Douglas-Peucker simplification of a wall polyline, given as indices into a
// point array: shared by the importers that simplify walls between junctions
// (labelled surfaces, label images), so both keep the same vertices.

#include <algorithm>
#include <cstddef>
#include <vector>

#include "tessella/tissue/vec3.hpp"

namespace tessella::io::detail {

/// Distance from p to the segment [a, b].
inline double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

/// Douglas-Peucker on chain[lo..hi] (its ends kept), setting keep[v] = 1 for
/// each kept inner vertex v; keep_one keeps the farthest inner vertex
/// whatever its distance (a wall that must not become a straight segment).
template <typename IndexT>
void douglasPeucker(const std::vector<IndexT>& chain, std::size_t lo, std::size_t hi, const std::vector<Vec3>& pos,
                    double tol, bool keep_one, std::vector<char>& keep) {
  if (hi <= lo + 1) return;
  double worst = -1;
  std::size_t at = lo;
  for (std::size_t i = lo + 1; i < hi; ++i) {
    const double d = pointSegmentDistance(pos[chain[i]], pos[chain[lo]], pos[chain[hi]]);
    if (d > worst) worst = d, at = i;
  }
  if (worst <= tol && !keep_one) return;
  keep[chain[at]] = 1;
  douglasPeucker(chain, lo, at, pos, tol, false, keep);
  douglasPeucker(chain, at, hi, pos, tol, false, keep);
}

}  // namespace tessella::io::detail
