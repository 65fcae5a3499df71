// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private helper of the batch edits (CellComplex::splitFaces, Tissue::splitCells):
// items claiming their element in parallel, so that an element given twice is found
// without a serial pass over every item. Internal to the tissue module.

#include <atomic>
#include <cstddef>
#include <cstdint>

#include "tessella/tissue/uninitialized_vector.hpp"

namespace tessella::detail {

/// Item i of [0, n) claims the element element_of(i): owner[element.index()] = i, in parallel
/// (OpenMP) from `min_parallel` items; `owner` holds -1 for every element on entry. Returns false
/// when some item's element is not live(element) or is claimed by another item: `owner` is then
/// partly written, and the caller refills it and runs its serial loop, which names the first
/// defect in item order.
template <typename ElementOf, typename Live>
bool claimInParallel(std::ptrdiff_t n, UninitializedVector<std::int32_t>& owner, ElementOf&& element_of,
                     Live&& live, std::ptrdiff_t min_parallel) {
  bool defect = false;
#pragma omp parallel for schedule(static) reduction(|| : defect) if (n >= min_parallel)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto element = element_of(i);
    std::int32_t unclaimed = -1;
    defect = defect || !live(element) ||
             !std::atomic_ref<std::int32_t>(owner[element.index()])
                  .compare_exchange_strong(unclaimed, static_cast<std::int32_t>(i), std::memory_order_relaxed);
  }
  return !defect;
}

}  // namespace tessella::detail
