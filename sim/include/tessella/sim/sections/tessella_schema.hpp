#pragma once
// The schema of a Tessella config file: the union of every section's keys.

#include "tessella/sim/config/schema.hpp"

namespace tessella::sim {

/// Built once, on first use. Top-level keys: rng_seed, tessella_version;
/// sections: tissue, time, output (see docs/config.md).
///
/// Extension point: a module adding a config section (e.g. growth:,
/// division:) writes <name>_section.hpp/.cpp with declare<Name>Section() and
/// read<Name>Section(), and calls the former in tessella_schema.cpp.
const Schema& tessellaSchema();

/// Version of the library, written to run.yaml.
const char* tessellaVersion();

}  // namespace tessella::sim
