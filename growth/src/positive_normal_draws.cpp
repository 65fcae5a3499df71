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
#include "tessella/tissue/uninitialized_vector.hpp"

namespace tessella::growth {

namespace {

[[maybe_unused]] void drawOneByOne(Rng& rng, double mean, double stddev, std::span<double> out) {
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
  // buffer (a bit fewer than the chunk needs on average); in one parallel
  // pass each try (two numbers) is turned into its uniforms by
  // generate_canonical itself (fed the buffered numbers), tested, and when
  // accepted gives its two values; then the tries are scanned serially and
  // their values dealt out in order. When the buffer holds more than is used,
  // the engine is put back and advanced by the numbers used. The rest of the
  // chunk is drawn pair by pair; a pair's second value not used by a chunk
  // starts the next one.
  constexpr std::size_t kChunk = std::size_t{1} << 18;  // values per chunk
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
  struct Try {
    double first, second;  // the pair's values, when accepted
    bool accepted;
  };
  // Not zeroed first (a serial write of megabytes): the engine fills `raw`,
  // the parallel pass sets every try's `accepted` and an accepted try's values.
  UninitializedVector<Rng::result_type> raw;
  UninitializedVector<Try> tries;
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
    // A try is accepted with probability pi / 4: 90 % of the expected need.
    const std::size_t n_tries = static_cast<std::size_t>(0.9 * static_cast<double>(want_pairs) / (M_PI / 4));
    const std::size_t n_raw = 2 * n_tries;
    const Rng saved = rng;
    raw.resize(n_raw);
    for (auto& r : raw) r = rng();
    tries.resize(n_tries);
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(n_tries);
#pragma omp parallel for schedule(static) if (m >= kParallelMinItems / 2)
    for (std::ptrdiff_t i = 0; i < m; ++i) {
      Replay replay{raw.data() + 2 * i};
      const double x = 2.0 * canonical(replay) - 1.0;
      const double y = 2.0 * canonical(replay) - 1.0;
      const double r2 = x * x + y * y;
      Try& t = tries[i];
      t.accepted = !(r2 > 1.0 || r2 == 0.0);
      if (!t.accepted) continue;
      const double mult = std::sqrt(-2 * std::log(r2) / r2);
      t.first = value(y * mult);
      t.second = value(x * mult);
    }
    // Dealt out in order; `consumed`: the numbers the one-by-one loop would
    // have drawn by now (every try scanned, or up to the pair of the last
    // value used, or up to the last pair when the chunk's pairs are all there).
    std::size_t consumed = n_raw, pairs = 0;
    for (std::size_t i = 0; i < n_tries; ++i) {
      const Try& t = tries[i];
      if (!t.accepted) continue;
      ++pairs;
      if (t.first > 0) out[filled++] = t.first;
      if (filled == goal) {
        carry = t.second;
        consumed = 2 * (i + 1);
        break;
      }
      if (t.second > 0) out[filled++] = t.second;
      if (filled == goal || pairs == want_pairs) {
        consumed = 2 * (i + 1);
        break;
      }
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
