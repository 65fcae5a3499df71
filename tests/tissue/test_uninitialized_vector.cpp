// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// UninitializedVector and its parallel growth (growInParallel,
// filledInParallel), and RaggedArray's batch edits that use them: the items
// and lists are those of the same edits made one item at a time on plain
// std::vectors, with 1 and 2 threads.
#include <catch2/catch.hpp>

#include <omp.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/ragged_array.hpp"
#include "tessella/tissue/uninitialized_vector.hpp"

using namespace tessella;

namespace {

// Lists of different lengths (0 to 6 items) with items made from their index.
std::uint32_t sizeOf(std::size_t i) { return static_cast<std::uint32_t>((i * 7 + 3) % 7); }
int itemOf(std::size_t i, std::size_t k) { return static_cast<int>(1000 * i + k); }

}  // namespace

TEST_CASE("uninitialized vector: items given a value keep it", "[tissue][uninitialized]") {
  UninitializedVector<int> v(4, 7);
  CHECK(v == UninitializedVector<int>{7, 7, 7, 7});
  v.push_back(8);
  v.insert(v.begin(), 2, 5);
  CHECK(v == UninitializedVector<int>{5, 5, 7, 7, 7, 7, 8});
  UninitializedVector<VertexId> handles;
  handles.emplace_back(3);
  CHECK(handles[0] == VertexId(3));
}

TEST_CASE("growInParallel keeps the items, and doubles the room when it must move them", "[tissue][uninitialized]") {
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    for (std::size_t n : {std::size_t{10}, 3 * kParallelCopyMin + 17}) {  // one thread's copy; the parallel copy
      UninitializedVector<std::int64_t> v;
      v.reserve(n);
      for (std::size_t i = 0; i < n; ++i) v.push_back(static_cast<std::int64_t>(i * i) - 5);
      REQUIRE(v.capacity() == n);
      growInParallel(v, n + 3);  // past the room: moves
      REQUIRE(v.size() == n + 3);
      CHECK(v.capacity() >= 2 * n);
      bool same = true;
      for (std::size_t i = 0; i < n; ++i) same = same && v[i] == static_cast<std::int64_t>(i * i) - 5;
      CHECK(same);
      const std::int64_t* at = v.data();
      growInParallel(v, n + 10);  // within the room: stays
      CHECK(v.data() == at);
      CHECK(v.size() == n + 10);
      CHECK(v[n - 1] == static_cast<std::int64_t>((n - 1) * (n - 1)) - 5);
      // A std::vector of a type whose default constructor writes nothing grows the same way.
      std::vector<std::array<float, 3>> w(n, {1.0f, 2.0f, float(threads)});
      growInParallel(w, 2 * n + 1);
      REQUIRE(w.size() == 2 * n + 1);
      CHECK(w[0] == std::array<float, 3>{1.0f, 2.0f, float(threads)});
      CHECK(w[n - 1] == std::array<float, 3>{1.0f, 2.0f, float(threads)});
    }
  }
  omp_set_num_threads(omp_get_num_procs());
}

TEST_CASE("filledInParallel writes every item", "[tissue][uninitialized]") {
  for (int threads : {1, 2})
    for (std::size_t n : {std::size_t{0}, std::size_t{5}, 2 * kParallelCopyMin + 1}) {
      omp_set_num_threads(threads);
      const UninitializedVector<std::int32_t> v = filledInParallel<std::int32_t>(n, -1);
      REQUIRE(v.size() == n);
      std::size_t wrong = 0;
      for (std::int32_t x : v) wrong += x != -1;
      CHECK(wrong == 0);
    }
  omp_set_num_threads(omp_get_num_procs());
}

TEST_CASE("ragged array: appended lists, moved lists and a parallel repack keep every list", "[tissue][ragged]") {
  const std::size_t n = 20000;  // above the parallel threshold of the batch edits and of repack
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    RaggedArray<int> r;
    std::vector<std::vector<int>> expected;
    // Half the lists pushed one by one, the other half appended in a batch and then written.
    for (std::size_t i = 0; i < n / 2; ++i) {
      std::vector<int> list;
      for (std::size_t k = 0; k < sizeOf(i); ++k) list.push_back(itemOf(i, k));
      r.pushList(std::span<const int>(list));
      expected.push_back(list);
    }
    std::vector<std::uint32_t> sizes;
    for (std::size_t i = n / 2; i < n; ++i) sizes.push_back(sizeOf(i));
    REQUIRE(r.appendLists(sizes) == n / 2);
    REQUIRE(r.size() == n);
    for (std::size_t i = n / 2; i < n; ++i) {
      REQUIRE(r.listSize(i) == sizeOf(i));
      auto list = r.mutableList(i);
      for (std::size_t k = 0; k < list.size(); ++k) list[k] = itemOf(i, k);
      expected.emplace_back(list.begin(), list.end());
    }
    // Every even list grows by 3 (they move to the end of the pool), then each gets its new items.
    std::vector<Index> grown;
    std::vector<std::uint32_t> new_sizes;
    for (std::size_t i = 0; i < n; i += 2) {
      grown.push_back(static_cast<Index>(i));
      new_sizes.push_back(sizeOf(i) + 3);
    }
    r.resizeLists(grown, new_sizes);
    for (std::size_t i = 0; i < n; i += 2) {
      auto list = r.mutableList(i);
      REQUIRE(list.size() == sizeOf(i) + 3);
      for (int k = 0; k < 3; ++k) {
        list[sizeOf(i) + k] = -k - 1;
        expected[i].push_back(-k - 1);
      }
    }
    auto same = [&] {
      std::size_t wrong = 0;
      for (std::size_t i = 0; i < n; ++i)
        wrong += std::vector<int>(r[i].begin(), r[i].end()) != expected[i];
      return wrong;
    };
    CHECK(same() == 0);
    const std::size_t before = r.bytes();
    r.repack();
    CHECK(same() == 0);
    CHECK(r.bytes() <= before);
    // Lists grown after the repack move again, the others stay.
    r.pushBack(1, 77);
    expected[1].push_back(77);
    CHECK(same() == 0);
  }
  omp_set_num_threads(omp_get_num_procs());
}
