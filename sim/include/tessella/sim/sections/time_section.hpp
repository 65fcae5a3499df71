// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The `time:` section: the simulated time span and the step.

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/sim/time_span.hpp"

namespace tessella::sim {

void declareTimeSection(Schema& schema);
/// Reads time.*; end < start or too many steps are ConfigErrors.
TimeSpan readTimeSection(const Config& config);

}  // namespace tessella::sim
