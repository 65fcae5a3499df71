// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/time_span.hpp"

#include <algorithm>
#include <cmath>

namespace tessella::sim {

std::size_t TimeSpan::numSteps() const {
  if (!(end > start)) return 0;
  if (origin_steps > 0) {
    // Counted as the uninterrupted run counts them, so both end together.
    const std::size_t total = TimeSpan{origin, end, dt}.numSteps();
    return total > origin_steps ? total - origin_steps : 0;
  }
  const double ratio = (end - start) / dt;
  // A span that is a multiple of dt up to rounding gets no sliver step.
  return static_cast<std::size_t>(std::ceil(ratio - 1e-9 * ratio));
}

double TimeSpan::timeAt(std::size_t k) const {
  if (k >= numSteps()) return std::max(start, end);
  if (origin_steps > 0) return origin + static_cast<double>(origin_steps + k) * dt;
  return start + static_cast<double>(k) * dt;
}

}  // namespace tessella::sim
