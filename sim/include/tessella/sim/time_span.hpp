// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// TimeSpan: the clock of a Simulation (no YAML: the `time:` section reads it,
// sections/time_section.hpp).

#include <cstddef>

namespace tessella::sim {

/// [start, end] in steps of dt. The last step is shortened to land exactly on
/// `end` when (end - start) is not a multiple of dt. Step k ends at
/// start + k * dt (computed, not accumulated, so there is no drift).
struct TimeSpan {
  double start = 0.0;
  double end = 10.0;
  double dt = 1.0;
  /// A restart continues its original run's clock: when origin_steps > 0,
  /// `start` is that run's time after origin_steps steps from `origin`, and
  /// step k of this span ends at origin + (origin_steps + k) * dt, exactly
  /// the time the uninterrupted run gives it (start + k * dt may differ in
  /// the last bits).
  double origin = 0.0;
  std::size_t origin_steps = 0;

  /// Number of steps from start to end (0 when end == start).
  std::size_t numSteps() const;
  /// Time after k steps (start for k = 0, end for k = numSteps()).
  double timeAt(std::size_t k) const;
  /// The clock this span runs on: its origin and the steps taken from it
  /// before the span's start ({start, 0} unless it continues a run).
  double clockOrigin() const { return origin_steps > 0 ? origin : start; }
};

/// Largest number of steps a config may ask for (a typo in dt must not hang a run).
inline constexpr double kMaxSteps = 1e9;

}  // namespace tessella::sim
