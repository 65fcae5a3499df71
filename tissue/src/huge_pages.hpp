// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Fresh arrays backed by transparent huge pages where the kernel allows it
// (tissue/src only). A bulk build (CellComplex::fromLoops) writes arrays of
// tens of MB once; at 4 KB a page, their first-touch page faults are a large
// share of its time. madvise(MADV_HUGEPAGE) on the 2 MB-aligned interior of
// one array, before anything is written to it, makes those faults 2 MB each
// (THP `madvise` mode). Only these arrays are advised: no process-wide malloc
// policy. A hint: where unsupported or refused, nothing changes.

#include <algorithm>
#include <cstddef>

#include "tessella/tissue/uninitialized_vector.hpp"

namespace tessella::detail {

/// Advises huge pages for the whole 2 MB pages inside [data, data + bytes);
/// does nothing for arrays below 4 MB or off Linux.
void adviseHugePages(const void* data, std::size_t bytes);

/// n unwritten items in storage advised for huge pages (see above).
template <typename T>
UninitializedVector<T> freshArray(std::size_t n) {
  UninitializedVector<T> v;
  v.reserve(n);  // allocates, writes nothing
  adviseHugePages(v.data(), n * sizeof(T));
  v.resize(n);
  return v;
}

/// n copies of value in storage advised for huge pages. Written on one
/// thread: a fill of a few MB costs less than a parallel region's team on a
/// busy machine.
template <typename T>
UninitializedVector<T> freshArray(std::size_t n, T value) {
  UninitializedVector<T> v = freshArray<T>(n);
  std::fill(v.begin(), v.end(), value);
  return v;
}

}  // namespace tessella::detail
