// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The table of division thresholds (when a cell divides: SizeThreshold's
// kinds, with the parameters each reads).
#include "tessella/growth/registries.hpp"

namespace tessella::growth {

const Registry<DivisionThresholdFactory>& divisionThresholds() {
  static const Registry<DivisionThresholdFactory> table(
      "division threshold",
      {{"fixed", "One `size` for all cells.",
        {ParamSpec("size", ParamType::Float, "Size above which a cell divides.").byDefault(1.0).above(0)},
        [](const ParamValues& p) {
          return blameParam("size", [&] { return SizeThreshold::fixed(p.getFloat("size")); });
        }},
       {"property", "Each cell's threshold is a cell property the model maintains.",
        {ParamSpec("property", ParamType::String, "Cell property (a float) holding each cell's threshold.")
             .byDefault(std::string("division_threshold"))},
        [](const ParamValues& p) {
          return blameParam("property", [&] { return SizeThreshold::fromProperty(p.getString("property")); });
        }},
       {"noisy", "Drawn per cell at birth from N(mean, stddev).",
        {ParamSpec("mean", ParamType::Float, "Mean of the noisy threshold.").byDefault(1.0).above(0),
         ParamSpec("stddev", ParamType::Float, "Standard deviation of the noisy threshold.").byDefault(0.1).atLeast(0)},
        [](const ParamValues& p) { return SizeThreshold::noisy(p.getFloat("mean"), p.getFloat("stddev")); }}});
  return table;
}

}  // namespace tessella::growth
