// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/time_section.hpp"

namespace tessella::sim {

void declareTimeSection(Schema& s) {
  s.section("time", "The simulated time span, in the model's time unit, and the step.");
  s.key("time.start", ValueType::Float, "Time of the initial tissue.").byDefault(0.0);
  s.key("time.end", ValueType::Float,
        "End of the run (>= start). When end - start is not a multiple of dt, the last step is "
        "shortened to end exactly here.")
      .byDefault(10.0);
  s.key("time.dt", ValueType::Float, "Length of one step.").byDefault(1.0).above(0);
}

TimeSpan readTimeSection(const Config& c) {
  TimeSpan t{c.getFloat("time.start"), c.getFloat("time.end"), c.getFloat("time.dt")};
  if (t.end < t.start)
    throw c.errorAt("time.end", "must be >= time.start (" + formatValue(t.start) + "), got " +
                                    formatValue(t.end));
  const double steps = (t.end - t.start) / t.dt;
  if (!(steps <= kMaxSteps))
    throw c.errorAt("time.dt", "(time.end - time.start) / time.dt = " + formatValue(steps) +
                                   " steps is more than the limit of " + formatValue(kMaxSteps) +
                                   "; got dt = " + formatValue(t.dt));
  return t;
}

}  // namespace tessella::sim
