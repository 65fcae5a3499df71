// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private: orders of 2D points along a Hilbert curve, for building a Delaunay
// triangulation (insertion order) and for visiting its cells (plain order).

#include <span>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::detail {

struct SpatialOrder2 {
  /// Biased randomised insertion order (BRIO, Amenta, Choi & Rote 2003):
  /// rounds of growing size (each about 4 times the last), each along a
  /// Hilbert curve. A point's round comes from a hash of its index, so the
  /// order is reproducible and independent of the thread count. Walks from
  /// the last inserted point stay short and the triangulation never degrades
  /// the way a purely sorted insertion can.
  std::vector<Index> insertion;
  /// All points along one Hilbert curve: consecutive points are close.
  std::vector<Index> hilbert;
};

/// Both orders of the points' (x, y), by counting sorts (linear time).
SpatialOrder2 spatialOrder2(std::span<const Vec3> points);

}  // namespace tessella::detail
