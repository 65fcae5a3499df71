// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One machine-readable line per benchmark figure, beside the human output:
//
//   FIGURE name=<name> value=<v> unit=<u> [baseline=<b> of=<what>] target=<t|none> better=<lower|higher>
//
// With a baseline (a reference timed in the same run), the figure is the
// ratio value / baseline and `target` bounds that ratio; without one,
// `target` bounds the value itself. `better` says which side of the target
// meets it; `none` is a figure no issue has set a target for (kNoTarget).
// bench/run_all collects these lines into one table.

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace tessella::bench {

enum class Better { Lower, Higher };

inline constexpr double kNoTarget = std::numeric_limits<double>::quiet_NaN();

inline std::string targetText(double target) {
  if (std::isnan(target)) return "none";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", target);
  return text;
}

/// A figure measured against a baseline of the same run: met when
/// value / baseline is at most (Lower) or at least (Higher) `target_ratio`.
inline void printFigure(const std::string& name, double value, const char* unit, double baseline,
                        const char* baseline_name, double target_ratio, Better better = Better::Lower) {
  std::printf("FIGURE name=%s value=%.6g unit=%s baseline=%.6g of=%s target=%s better=%s\n", name.c_str(), value,
              unit, baseline, baseline_name, targetText(target_ratio).c_str(),
              better == Better::Lower ? "lower" : "higher");
  std::fflush(stdout);
}

/// A figure with an absolute target (no baseline).
inline void printFigure(const std::string& name, double value, const char* unit, double target,
                        Better better = Better::Lower) {
  std::printf("FIGURE name=%s value=%.6g unit=%s target=%s better=%s\n", name.c_str(), value, unit,
              targetText(target).c_str(), better == Better::Lower ? "lower" : "higher");
  std::fflush(stdout);
}

}  // namespace tessella::bench
