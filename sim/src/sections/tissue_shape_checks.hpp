// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// checkTissueShape(): the config keys that assume a dimension or embedding of
// the tissue (elasticity models, growth.surface, boundary regions z_min/z_max,
// z components, 3D-only mesh keys, a restart's snapshot against the generator
// section the config still describes) checked against the tissue the config
// builds, as ConfigErrors naming the key and both dimensions.

#include "tessella/sim/sections/simulation_config.hpp"

namespace tessella::sim::detail {

void checkTissueShape(const SimulationConfig& config);

}  // namespace tessella::sim::detail
