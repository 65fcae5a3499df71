// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstring>
#include <random>
#include <vector>

#include "tessella/growth/positive_normal_draws.hpp"

using namespace tessella;
using namespace tessella::growth;

namespace {

// The definition: one std::normal_distribution, drawn value after value, each redrawn until positive.
std::vector<double> oneByOne(Rng& rng, double mean, double stddev, std::size_t n) {
  std::normal_distribution<double> draw(mean, stddev);
  std::vector<double> out(n);
  for (double& v : out) {
    do v = draw(rng);
    while (!(v > 0));
  }
  return out;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace

TEST_CASE("drawPositiveNormals gives the one-by-one draws and leaves the engine where they do",
          "[growth][threshold]") {
  // Sizes below and above the parallel threshold and the chunk of 2^16
  // values, odd and even (an odd count leaves a pair's second value unused, a
  // chunk may end inside a pair); spreads from none to one where almost half
  // of the draws are refused (mean 0.1, stddev 1: 46 % negative).
  const int threads = GENERATE(1, 2);
  const std::size_t n = GENERATE(std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{4096},
                                 std::size_t{10001}, std::size_t{50000}, std::size_t{131072},
                                 std::size_t{140001});
  const double stddev = GENERATE(0.0, 0.1, 1.0);
  const double mean = GENERATE(0.1, 1.1);
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  Rng a(17 + n), b(17 + n);
  const std::vector<double> expected = oneByOne(a, mean, stddev, n);
  std::vector<double> got(n);
  drawPositiveNormals(b, mean, stddev, got);
  CHECK(sameBits(got, expected));
  CHECK(a == b);  // the same engine state: the next draws agree too
  for (double v : got) REQUIRE(v > 0);
  omp_set_num_threads(before);
}
