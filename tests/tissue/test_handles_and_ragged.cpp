// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/ragged_array.hpp"

using namespace tessella;

TEST_CASE("handles are invalid by default and typed", "[tissue][handles]") {
  VertexId v;
  CHECK_FALSE(v.valid());
  CHECK(VertexId(3).valid());
  CHECK(VertexId(3) == VertexId(3));
  CHECK(VertexId(2) < VertexId(3));
  STATIC_REQUIRE_FALSE(std::is_convertible_v<VertexId, EdgeId>);
  OrientedEdge oe(EdgeId(7), true);
  CHECK(oe.handle() == EdgeId(7));
  CHECK(oe.reversed());
  CHECK(oe.sign() == -1);
  CHECK(oe.flipped().sign() == 1);
  CHECK_FALSE(OrientedEdge().handle().valid());
}

TEST_CASE("ragged array keeps lists through growth, relocation and compaction", "[tissue][ragged]") {
  RaggedArray<int> r;
  for (int i = 0; i < 100; ++i) r.pushList({i, i + 1});
  // Grow every list well past its capacity: lists relocate, garbage gets repacked.
  for (int round = 0; round < 20; ++round)
    for (int i = 0; i < 100; ++i) r.pushBack(i, 1000 * round + i);
  for (int i = 0; i < 100; ++i) {
    auto l = r[i];
    REQUIRE(l.size() == 22);
    CHECK(l[0] == i);
    CHECK(l[1] == i + 1);
    CHECK(l[21] == 19000 + i);
  }
  r.insert(5, 0, -1);
  CHECK(r[5][0] == -1);
  CHECK(r.eraseValue(5, -1));
  CHECK_FALSE(r.eraseValue(5, -12345));
  CHECK(r.replaceValue(5, 5, 55));
  CHECK(r[5][0] == 55);
  // Assigning a list from a view of itself must not read freed memory.
  std::vector<int> longer(r[7].begin(), r[7].end());
  longer.insert(longer.end(), 50, 9);
  r.assign(7, longer);
  CHECK(r[7].size() == 72);
  std::vector<Index> map(100, kInvalidIndex);
  map[7] = 0;
  map[3] = 1;
  r.compact(map, 2, [](int x) { return x * 2; });
  REQUIRE(r.size() == 2);
  CHECK(r[0].size() == 72);
  CHECK(r[0][0] == 14);
  CHECK(r[1][0] == 6);
}

TEST_CASE("ragged array built from a pool keeps its lists where they lie", "[tissue][ragged]") {
  // Lists 0..2 laid out in the pool as 2, 0, 1 with a hole (garbage) after list 0.
  const std::vector<std::uint32_t> at = {3, 7, 0}, sizes = {2, 1, 3};
  RaggedArray<int> r = RaggedArray<int>::fromPool({20, 21, 22, 0, 1, -9, -9, 10}, at, sizes);
  REQUIRE(r.size() == 3);
  CHECK(std::vector<int>(r[0].begin(), r[0].end()) == std::vector<int>{0, 1});
  CHECK(std::vector<int>(r[1].begin(), r[1].end()) == std::vector<int>{10});
  CHECK(std::vector<int>(r[2].begin(), r[2].end()) == std::vector<int>{20, 21, 22});
  // Lists 0 and 1 grow past their room and move; nothing else changes.
  r.pushBack(0, 2);
  r.pushBack(0, 3);
  r.pushBack(1, 11);
  CHECK(std::vector<int>(r[0].begin(), r[0].end()) == std::vector<int>{0, 1, 2, 3});
  CHECK(std::vector<int>(r[1].begin(), r[1].end()) == std::vector<int>{10, 11});
  CHECK(std::vector<int>(r[2].begin(), r[2].end()) == std::vector<int>{20, 21, 22});
  r.repack();
  CHECK(std::vector<int>(r[0].begin(), r[0].end()) == std::vector<int>{0, 1, 2, 3});
  CHECK(std::vector<int>(r[1].begin(), r[1].end()) == std::vector<int>{10, 11});
}
