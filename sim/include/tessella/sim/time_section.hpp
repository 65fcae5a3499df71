#pragma once
// The `time:` section: the simulated time span and the step.

#include <cstddef>

#include "tessella/sim/config.hpp"
#include "tessella/sim/schema.hpp"

namespace tessella::sim {

/// [start, end] in steps of dt. The last step is shortened to land exactly on
/// `end` when (end - start) is not a multiple of dt. Step k ends at
/// start + k * dt (computed, not accumulated, so there is no drift).
struct TimeSpan {
  double start = 0.0;
  double end = 10.0;
  double dt = 1.0;

  /// Number of steps from start to end (0 when end == start).
  std::size_t numSteps() const;
  /// Time after k steps (start for k = 0, end for k = numSteps()).
  double timeAt(std::size_t k) const;
};

/// Largest number of steps a config may ask for (a typo in dt must not hang a run).
inline constexpr double kMaxSteps = 1e9;

void declareTimeSection(Schema& schema);
/// Reads time.*; end < start or too many steps are ConfigErrors.
TimeSpan readTimeSection(const Config& config);

}  // namespace tessella::sim
