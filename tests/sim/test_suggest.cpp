// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include "tessella/sim/config/suggest.hpp"

using namespace tessella::sim;

TEST_CASE("editDistance counts insertions, deletions, substitutions and transpositions", "[sim][suggest]") {
  CHECK(editDistance("", "") == 0);
  CHECK(editDistance("abc", "") == 3);
  CHECK(editDistance("", "abc") == 3);
  CHECK(editDistance("kitten", "sitting") == 3);  // the textbook Levenshtein example
  CHECK(editDistance("count", "cuont") == 1);      // one adjacent transposition
  CHECK(editDistance("count", "cout") == 1);
  CHECK(editDistance("ca", "abc") == 3);           // optimal string alignment, not full Damerau (2)
  CHECK(editDistance("lloyd_iterations", "lloyd_iterations") == 0);
}

TEST_CASE("editDistance is symmetric", "[sim][suggest]") {
  const char* words[] = {"count", "cuont", "domain", "dommain", "radius", "raduis", "x"};
  for (const char* a : words)
    for (const char* b : words) CHECK(editDistance(a, b) == editDistance(b, a));
}

TEST_CASE("closestMatch suggests plausible typos only", "[sim][suggest]") {
  const std::vector<std::string> keys{"domain", "count", "seed_file", "lloyd_iterations", "rectangle", "disk"};
  CHECK(closestMatch("cuont", keys) == std::optional<std::string>("count"));
  CHECK(closestMatch("Count", keys) == std::optional<std::string>("count"));
  CHECK(closestMatch("seedfile", keys) == std::optional<std::string>("seed_file"));
  CHECK(closestMatch("loyd_iterations", keys) == std::optional<std::string>("lloyd_iterations"));
  CHECK(closestMatch("dsk", keys) == std::optional<std::string>("disk"));
  CHECK_FALSE(closestMatch("velocity", keys).has_value());
  CHECK_FALSE(closestMatch("ab", keys).has_value());
  CHECK_FALSE(closestMatch("x", {}).has_value());
}
