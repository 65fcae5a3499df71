// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The `network:` section: a cell-level regulatory network (species per cell,
// reactions, passive transport, PIN efflux) integrated by CVODE, read into a
// NetworkSpec (stages/network_stage.hpp). docs/networks.md.

#include <cstdint>

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/sim/stages/network_stage.hpp"

namespace tessella::sim {

class StageList;

void declareNetworkSection(Schema& schema);
/// `noise_seed`: the run's rng_seed (the initial noise is drawn from it).
NetworkSpec readNetworkSection(const Config& config, std::uint64_t noise_seed);
void addNetworkStage(const NetworkSpec& network, StageList& stages);

}  // namespace tessella::sim
