// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// resizeDiscarding(v, n): v.resize(n) for arrays rewritten whole before they
// are read again (scratch and cache arrays: the growth integrator's
// positions and velocities, the geometry cache), which never copies the old
// items.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tessella {

/// v.resize(n) where every item is written before it is read again (the old
/// values are not needed). When n exceeds the capacity, the old storage is
/// released instead of copied and the new one (at least twice the old size)
/// is not written for types whose default constructor writes nothing (such
/// as Eigen's fixed-size vectors): the parallel passes that fill it take the
/// first touch of its pages, each thread those of its own items, instead of
/// one thread copying the old items and faulting their pages in.
template <typename T, typename A>
void resizeDiscarding(std::vector<T, A>& v, std::size_t n) {
  if (n > v.capacity()) {
    const std::size_t capacity = std::max(n, 2 * v.size());
    std::vector<T, A>(v.get_allocator()).swap(v);  // the old storage is freed first
    v.reserve(capacity);
  }
  v.resize(n);
}

}  // namespace tessella
