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
  std::vector<std::uint64_t> table;          // edge + 1 (high 32 bits), uses backward / forward (16 bits each)
  std::vector<std::uint32_t> touched;        // the slots in use
  std::vector<std::pair<Index, int>> uses;   // the sorted uses when a surface fails
};

// The lowest edge not used exactly once in each direction, from the sorted
// uses (or kInvalidIndex).
template <typename LoopOf>
inline Index firstBadEdge(std::span<const OrientedFace> faces, LoopOf loopOf, ClosedSurfaceScratch& s) {
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
    if (fwd != 1 || bwd != 1) return uses[i].first;
    i = j;
  }
  return kInvalidIndex;
}

// An oriented surface is closed and consistently oriented when every edge is
// traversed exactly once in each direction by its faces' loops.
// The uses are counted in a small open-addressing table keyed by edge (linear
// in the number of uses; at most a quarter full, and updated without a branch
// on whether an edge was seen before); only a failing surface is sorted, to
// name its lowest bad edge. (A surface of 2^16 uses or more, whose counts
// could overflow, is sorted too.)
template <typename LoopOf>
inline bool closedOrientedSurface(std::span<const OrientedFace> faces, LoopOf loopOf, Index* bad_edge,
                                  ClosedSurfaceScratch* scratch = nullptr) {
  ClosedSurfaceScratch own;
  ClosedSurfaceScratch& s = scratch ? *scratch : own;
  std::size_t count = 0;
  for (OrientedFace of : faces) count += loopOf(of.handle()).size();
  if (count >= (std::size_t{1} << 16)) {
    const Index bad = firstBadEdge(faces, loopOf, s);
    if (bad_edge && bad != kInvalidIndex) *bad_edge = bad;
    return bad == kInvalidIndex;
  }
  std::size_t size = 32;  // each edge is used twice: at most a quarter full
  while (size < 2 * count) size *= 2;
  if (s.table.size() < size) s.table.assign(size, 0);
  if (s.touched.size() < count) s.touched.resize(count);
  const std::size_t mask = size - 1;
  std::size_t used = 0;
  for (OrientedFace of : faces) {
    for (OrientedEdge oe : loopOf(of.handle())) {
      const std::uint64_t key = static_cast<std::uint64_t>(oe.handle().index()) + 1;
      const int shift = oe.reversed() == of.reversed() ? 0 : 16;
      std::size_t i = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & mask;
      std::uint64_t slot;
      while ((slot = s.table[i]) != 0 && (slot >> 32) != key) i = (i + 1) & mask;
      s.touched[used] = static_cast<std::uint32_t>(i);
      used += slot == 0;
      s.table[i] = (key << 32) | ((slot & 0xffffffffu) + (std::uint64_t{1} << shift));
    }
  }
  bool closed = true;
  for (std::size_t k = 0; k < used; ++k) {  // clears the table for the next call
    std::uint64_t& slot = s.table[s.touched[k]];
    closed &= (slot & 0xffffffffu) == 0x10001u;
    slot = 0;
  }
  if (closed || !bad_edge) return closed;
  *bad_edge = firstBadEdge(faces, loopOf, s);
  return false;
}

}  // namespace tessella::detail
