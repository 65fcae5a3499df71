// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// ProgressMeter: rate-limited progress lines for long runs. It formats, the
// app prints (library code never writes to a terminal).

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

namespace tessella::sim {

class ProgressMeter {
 public:
  using Clock = std::chrono::steady_clock;

  /// At most one line per `interval`, plus the final one.
  ProgressMeter(std::size_t total_steps, std::chrono::milliseconds interval,
                Clock::time_point start = Clock::now());

  /// A line such as "step 40/100 (40%)  t = 4  cells 120  elapsed 2.1 s  ETA 3.2 s"
  /// when one is due (the interval has passed since the last line, or this
  /// is the last step), else nothing.
  std::optional<std::string> update(std::size_t steps_done, double time, std::size_t cells,
                                    Clock::time_point now = Clock::now());

 private:
  std::size_t total_;
  std::chrono::milliseconds interval_;
  Clock::time_point start_;
  std::optional<Clock::time_point> last_line_;
};

/// "850 ms", "2.1 s", "3 min 05 s", "1 h 02 min".
std::string formatDuration(std::chrono::duration<double> d);

}  // namespace tessella::sim
