// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/positive_normal_draws.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "tessella/growth/parallel_threshold.hpp"

namespace tessella::growth {

namespace {

void drawOneByOne(Rng& rng, double mean, double stddev, std::span<double> out) {
  std::normal_distribution<double> draw(mean, stddev);
  for (double& v : out) {
    do v = draw(rng);
    while (!(v > 0));
  }
}

}  // namespace

void drawPositiveNormals(Rng& rng, double mean, double stddev, std::span<double> out) {
#if defined(__GLIBCXX__)
  // libstdc++'s normal_distribution::operator() (bits/random.tcc) is
  // Marsaglia's polar method: uniforms u1, u2 (generate_canonical<double, 53>
  // of the engine), x = 2 u1 - 1, y = 2 u2 - 1, redrawn until 0 < x^2 + y^2
  // <= 1; then y * mult is returned and x * mult kept for the next call, each
  // value becoming value * stddev + mean. A value that is not positive is
  // followed by the next one of the stream.
  //
  // Here, chunk by chunk: the engine's raw numbers are drawn serially into a
  // buffer (the only serial work besides pairing; a bit fewer numbers than
  // the chunk needs on average), turned into uniforms in parallel by
  // generate_canonical itself (fed the buffered numbers), paired and tested
  // serially, the values computed in parallel and dealt out in order. When
  // the buffer holds more than is used, the engine is put back and advanced
  // by the numbers used. The rest of the chunk is drawn pair by pair; a
  // pair's second value not used by a chunk starts the next one.
  constexpr std::size_t kChunk = std::size_t{1} << 16;  // values per chunk
  struct Replay {  // the engine's interface, giving buffered numbers
    using result_type = Rng::result_type;
    static constexpr result_type min() { return Rng::min(); }
    static constexpr result_type max() { return Rng::max(); }
    const result_type* next;
    result_type operator()() { return *next++; }
  };
  auto canonical = [](auto& engine) {
    return std::generate_canonical<double, std::numeric_limits<double>::digits>(engine);
  };
  auto value = [&](double v) { return v * stddev + mean; };
  struct Pair {
    double x, y, r2;
    std::size_t end;  // buffered numbers used up to this pair's, included
  };
  std::vector<Rng::result_type> raw;
  std::vector<double> uniform, values;
  std::vector<Pair> pairs;
  std::optional<double> carry;  // the unused second value of the last pair
  std::size_t filled = 0;
  while (filled < out.size()) {
    if (carry) {
      const double v = *carry;
      carry.reset();
      if (v > 0) out[filled++] = v;
      continue;
    }
    const std::size_t goal = filled + std::min(kChunk, out.size() - filled);
    const std::size_t want_pairs = (goal - filled + 1) / 2;
    // Two numbers per try, a try accepted with probability pi / 4: 90 % of the expected need.
    const std::size_t n_raw = 2 * static_cast<std::size_t>(0.9 * static_cast<double>(want_pairs) / (M_PI / 4));
    const Rng saved = rng;
    raw.resize(n_raw);
    for (auto& r : raw) r = rng();
    uniform.resize(n_raw);
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(n_raw);
#pragma omp parallel for schedule(static) if (m >= kParallelMinItems)
    for (std::ptrdiff_t i = 0; i < m; ++i) {
      Replay replay{raw.data() + i};
      uniform[i] = canonical(replay);
    }
    pairs.clear();
    for (std::size_t i = 0; i < n_raw && pairs.size() < want_pairs; i += 2) {
      const double x = 2.0 * uniform[i] - 1.0, y = 2.0 * uniform[i + 1] - 1.0;
      const double r2 = x * x + y * y;
      if (!(r2 > 1.0 || r2 == 0.0)) pairs.push_back(Pair{x, y, r2, i + 2});
    }
    values.resize(2 * pairs.size());
    const std::ptrdiff_t np = static_cast<std::ptrdiff_t>(pairs.size());
#pragma omp parallel for schedule(static) if (np >= kParallelMinItems / 2)
    for (std::ptrdiff_t i = 0; i < np; ++i) {
      const Pair& p = pairs[i];
      const double mult = std::sqrt(-2 * std::log(p.r2) / p.r2);
      values[2 * i] = value(p.y * mult);
      values[2 * i + 1] = value(p.x * mult);
    }
    std::size_t used = 0;  // values of the buffer used
    for (; used < values.size() && filled < goal; ++used)
      if (values[used] > 0) out[filled++] = values[used];
    // The numbers the one-by-one loop would have drawn by now: up to the pair
    // of the last value used, or every try when all pairs were used and fell short.
    std::size_t consumed = n_raw;
    if (used < values.size()) {
      consumed = pairs[(used - 1) / 2].end;
      if (used % 2 == 1) carry = values[used];
    } else if (pairs.size() == want_pairs && !pairs.empty()) {
      consumed = pairs.back().end;
    }
    if (consumed < n_raw) {
      rng = saved;
      rng.discard(consumed);
    }
    while (filled < goal && !carry) {
      double x, y, r2;
      do {
        x = 2.0 * canonical(rng) - 1.0;
        y = 2.0 * canonical(rng) - 1.0;
        r2 = x * x + y * y;
      } while (r2 > 1.0 || r2 == 0.0);
      const double mult = std::sqrt(-2 * std::log(r2) / r2);
      const double first = value(y * mult), second = value(x * mult);
      if (first > 0) out[filled++] = first;
      if (filled < goal) {
        if (second > 0) out[filled++] = second;
      } else {
        carry = second;
      }
    }
  }
#else
  drawOneByOne(rng, mean, stddev, out);
#endif
}

}  // namespace tessella::growth
