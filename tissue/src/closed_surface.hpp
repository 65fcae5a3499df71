// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The closed-surface test of a volume's faces, shared by addVolume and the
// bulk construction from a layout (tissue/src only).

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tessella/tissue/handles.hpp"

namespace tessella::detail {

// Reused memory of closedOrientedSurface, so that a caller checking many
// surfaces allocates once.
struct ClosedSurfaceScratch {
  std::vector<std::uint64_t> table;          // edge + 1 (high 32 bits), uses forward / backward (low bits)
  std::vector<std::pair<Index, int>> uses;   // the sorted uses when a surface fails
};

// An oriented surface is closed and consistently oriented when every edge is
// traversed exactly once in each direction by its faces' loops.
// The uses are counted in a small open-addressing table keyed by edge (linear
// in the number of uses); only a failing surface is sorted, to name its lowest
// bad edge.
template <typename LoopOf>
inline bool closedOrientedSurface(std::span<const OrientedFace> faces, LoopOf loopOf, Index* bad_edge,
                                  ClosedSurfaceScratch* scratch = nullptr) {
  ClosedSurfaceScratch own;
  ClosedSurfaceScratch& s = scratch ? *scratch : own;
  std::size_t count = 0;
  for (OrientedFace of : faces) count += loopOf(of.handle()).size();
  std::size_t size = 16;  // each edge is used twice: at most half full
  while (size < count) size *= 2;
  if (s.table.size() < size) s.table.assign(size, 0);
  const std::size_t mask = size - 1;
  // Per slot: forward uses in bits 0-1, backward uses in bits 2-3 (saturating at 2).
  for (OrientedFace of : faces) {
    for (OrientedEdge oe : loopOf(of.handle())) {
      const std::uint64_t key = static_cast<std::uint64_t>(oe.handle().index()) + 1;
      const int shift = oe.reversed() == of.reversed() ? 0 : 2;
      std::size_t i = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & mask;
      while (s.table[i] != 0 && (s.table[i] >> 32) != key) i = (i + 1) & mask;
      std::uint64_t& slot = s.table[i];
      if (slot == 0) slot = key << 32;
      if (((slot >> shift) & 3u) < 2) slot += std::uint64_t{1} << shift;
    }
  }
  bool closed = true;
  for (std::size_t i = 0; i < size; ++i) {  // clears the table for the next call (branch-free)
    const std::uint64_t slot = s.table[i];
    closed &= slot == 0 || (slot & 15u) == 5u;
    s.table[i] = 0;
  }
  if (closed || !bad_edge) return closed;
  std::vector<std::pair<Index, int>>& uses = s.uses;  // (edge, +1 forward / -1 backward)
  uses.clear();
  for (OrientedFace of : faces) {
    for (OrientedEdge oe : loopOf(of.handle())) {
      const bool forward = oe.reversed() == of.reversed();
      uses.emplace_back(oe.handle().index(), forward ? 1 : -1);
    }
  }
  std::sort(uses.begin(), uses.end());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    int fwd = 0, bwd = 0;
    while (j < uses.size() && uses[j].first == uses[i].first) {
      (uses[j].second > 0 ? fwd : bwd)++;
      ++j;
    }
    if (fwd != 1 || bwd != 1) {
      *bad_edge = uses[i].first;
      return false;
    }
    i = j;
  }
  return false;  // (not reached: the table found a bad edge)
}

}  // namespace tessella::detail
