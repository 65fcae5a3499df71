// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// parallelPrefixSum: exclusive prefix sums of per-item counts, in parallel
// (OpenMP), for the numbering of batch edits (CellComplex::splitFaces, the
// batch edits of RaggedArray): each thread sums its contiguous share of the
// items, the shares' offsets are summed in thread order, then each thread
// hands out the offsets of its items. Counts are integers, so every offset
// is the one the serial loop gives, for any number of threads.

#include <omp.h>

#include <cstddef>
#include <vector>

namespace tessella {

/// Below this many items the sums run on one thread (a team costs more).
inline constexpr std::ptrdiff_t kParallelPrefixSumMin = 4096;

/// With c_i = count(i) (an integer of type Sum, >= 0), calls
/// emit(i, c_0 + ... + c_{i-1}) once for every i in [0, n), and returns the
/// sum of all c_i. In parallel for n >= kParallelPrefixSumMin: count(i) is
/// then called twice for each i (it must not change between the calls),
/// and emit is called from several threads, each i from one thread.
template <typename Sum, typename Count, typename Emit>
Sum parallelPrefixSum(std::ptrdiff_t n, Count&& count, Emit&& emit) {
  if (n < kParallelPrefixSumMin) {
    Sum sum = 0;
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const Sum c = count(i);
      emit(i, sum);
      sum += c;
    }
    return sum;
  }
  std::vector<Sum> share_at;  // where each thread's share starts, then the total
#pragma omp parallel
  {
    const std::ptrdiff_t threads = omp_get_num_threads(), me = omp_get_thread_num();
    const std::ptrdiff_t lo = n * me / threads, hi = n * (me + 1) / threads;
#pragma omp single
    share_at.assign(static_cast<std::size_t>(threads) + 1, 0);
    Sum sum = 0;
    for (std::ptrdiff_t i = lo; i < hi; ++i) sum += count(i);
    share_at[static_cast<std::size_t>(me) + 1] = sum;
#pragma omp barrier
#pragma omp single
    for (std::size_t k = 1; k < share_at.size(); ++k) share_at[k] += share_at[k - 1];
    sum = share_at[static_cast<std::size_t>(me)];
    for (std::ptrdiff_t i = lo; i < hi; ++i) {
      const Sum c = count(i);
      emit(i, sum);
      sum += c;
    }
  }
  return share_at.back();
}

}  // namespace tessella
