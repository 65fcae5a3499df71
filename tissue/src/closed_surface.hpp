// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The closed-surface test of a volume's faces, shared by addVolume and the
// bulk construction from a layout (tissue/src only).

#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include "tessella/tissue/handles.hpp"

namespace tessella::detail {

// An oriented surface is closed and consistently oriented when every edge is
// traversed exactly once in each direction by its faces' loops.
// `scratch` (optional) holds the edge uses, so that a caller checking many
// surfaces allocates once.
template <typename LoopOf>
inline bool closedOrientedSurface(std::span<const OrientedFace> faces, LoopOf loopOf, Index* bad_edge,
                                  std::vector<std::pair<Index, int>>* scratch = nullptr) {
  std::vector<std::pair<Index, int>> own;
  std::vector<std::pair<Index, int>>& uses = scratch ? *scratch : own;  // (edge, +1 forward / -1 backward)
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
      if (bad_edge) *bad_edge = uses[i].first;
      return false;
    }
    i = j;
  }
  return true;
}

}  // namespace tessella::detail
