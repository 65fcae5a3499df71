// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/progress_meter.hpp"

#include <cmath>
#include <cstdio>

namespace tessella::sim {

ProgressMeter::ProgressMeter(std::size_t total_steps, std::chrono::milliseconds interval, Clock::time_point start)
    : total_(total_steps), interval_(interval), start_(start) {}

std::string formatDuration(std::chrono::duration<double> d) {
  const double s = std::max(0.0, d.count());
  char buf[64];
  if (s < 1.0) {
    std::snprintf(buf, sizeof buf, "%.0f ms", s * 1e3);
  } else if (s < 60.0) {
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  } else if (s < 3600.0) {
    const auto total = static_cast<long>(std::lround(s));
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", total / 60, total % 60);
  } else {
    const auto minutes = static_cast<long>(std::lround(s / 60.0));
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", minutes / 60, minutes % 60);
  }
  return buf;
}

std::optional<std::string> ProgressMeter::update(std::size_t steps_done, double time, std::size_t cells,
                                                 Clock::time_point now) {
  const bool last = steps_done >= total_;
  if (!last && last_line_ && now - *last_line_ < interval_) return std::nullopt;
  if (!last && !last_line_ && now - start_ < interval_) return std::nullopt;  // short runs stay quiet
  last_line_ = now;
  const std::chrono::duration<double> elapsed = now - start_;
  char head[160];
  const double percent = total_ ? 100.0 * static_cast<double>(steps_done) / static_cast<double>(total_) : 100.0;
  std::snprintf(head, sizeof head, "step %zu/%zu (%.0f%%)  t = %g  cells %zu  elapsed ", steps_done, total_,
                percent, time, cells);
  std::string line = head + formatDuration(elapsed);
  if (!last && steps_done > 0) {
    const double per_step = elapsed.count() / static_cast<double>(steps_done);
    line += "  ETA " + formatDuration(std::chrono::duration<double>(per_step * static_cast<double>(total_ - steps_done)));
  }
  return line;
}

}  // namespace tessella::sim
