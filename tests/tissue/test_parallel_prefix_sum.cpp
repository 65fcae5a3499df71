// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// parallelPrefixSum: every item gets the sum of the counts before it (the
// serial running sum, computed independently here), exactly once, with 1 and
// 2 threads, below and above the parallel threshold.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstdint>
#include <vector>

#include "tessella/tissue/parallel_prefix_sum.hpp"

using namespace tessella;

TEST_CASE("parallelPrefixSum hands every item the sum of the counts before it", "[tissue][prefix_sum]") {
  // Counts 0..4 in a pattern with runs of zeros: c_i = (i * i) % 5 for i % 3 != 0, else 0.
  auto count = [](std::ptrdiff_t i) -> std::uint32_t { return i % 3 == 0 ? 0 : static_cast<std::uint32_t>(i * i % 5); };
  for (int threads : {1, 2})
    for (std::ptrdiff_t n : {std::ptrdiff_t{0}, std::ptrdiff_t{1}, kParallelPrefixSumMin - 1, kParallelPrefixSumMin,
                             3 * kParallelPrefixSumMin + 7}) {
      omp_set_num_threads(threads);
      std::vector<std::uint32_t> before(static_cast<std::size_t>(n), 0xffffffffu);
      std::vector<int> calls(static_cast<std::size_t>(n), 0);
      const std::uint32_t total = parallelPrefixSum<std::uint32_t>(n, count, [&](std::ptrdiff_t i, std::uint32_t at) {
        before[static_cast<std::size_t>(i)] = at;
        ++calls[static_cast<std::size_t>(i)];  // each i from one thread: no race
      });
      std::uint32_t running = 0;
      std::size_t wrong = 0, not_once = 0;
      for (std::ptrdiff_t i = 0; i < n; ++i) {
        wrong += before[static_cast<std::size_t>(i)] != running;
        not_once += calls[static_cast<std::size_t>(i)] != 1;
        running += count(i);
      }
      INFO("threads " << threads << ", n " << n);
      CHECK(wrong == 0);
      CHECK(not_once == 0);
      CHECK(total == running);
    }
  omp_set_num_threads(omp_get_num_procs());
}

TEST_CASE("parallelPrefixSum numbers the items passing a test in order (a parallel filter)", "[tissue][prefix_sum]") {
  // The multiples of 7 below n, gathered in order: the k-th is 7 k.
  const std::ptrdiff_t n = 100000;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    std::vector<std::ptrdiff_t> kept(static_cast<std::size_t>(n), -1);
    const std::ptrdiff_t m = parallelPrefixSum<std::ptrdiff_t>(
        n, [](std::ptrdiff_t i) { return std::ptrdiff_t{i % 7 == 0}; },
        [&](std::ptrdiff_t i, std::ptrdiff_t at) {
          if (i % 7 == 0) kept[static_cast<std::size_t>(at)] = i;
        });
    CHECK(m == (n + 6) / 7);
    std::size_t wrong = 0;
    for (std::ptrdiff_t k = 0; k < m; ++k) wrong += kept[static_cast<std::size_t>(k)] != 7 * k;
    CHECK(wrong == 0);
    CHECK(kept[static_cast<std::size_t>(m)] == -1);
  }
  omp_set_num_threads(omp_get_num_procs());
}
