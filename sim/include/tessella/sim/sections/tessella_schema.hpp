// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The schema of a Tessella config file: the union of every section's keys.

#include "tessella/sim/config/schema.hpp"

namespace tessella::sim {

/// Built once, on first use. Top-level keys: rng_seed, tessella_version;
/// sections: tissue, time, then those of the table sectionUnits()
/// (sections/simulation_config.hpp), in its order (see docs/config.md).
const Schema& tessellaSchema();

/// Version of the library, written to run.yaml.
const char* tessellaVersion();

}  // namespace tessella::sim
