// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/tessella_schema.hpp"

#include "tessella/sim/sections/simulation_config.hpp"

#ifndef TESSELLA_VERSION
#error "TESSELLA_VERSION must be defined by the build (sim/CMakeLists.txt)"
#endif

namespace tessella::sim {

namespace {
Schema makeSchema() {
  Schema s;
  s.key("tessella_version", ValueType::String,
        "Version of Tessella that wrote this file. Informational: run.yaml records it, and a "
        "different version only adds a note.")
      .whenAbsent("not recorded");
  s.key("rng_seed", ValueType::Int,
        "Seed of every random draw of the run (random seed points, random division planes): the "
        "same configuration and seed give the same result.")
      .atLeast(0)
      .whenAbsent("drawn from the system's random source and recorded in run.yaml");
  declareTissueSection(s);
  declareTimeSection(s);
  for (const SectionUnit& unit : sectionUnits()) unit.declare(s);
  return s;
}
}  // namespace

const Schema& tessellaSchema() {
  static const Schema schema = makeSchema();
  return schema;
}

const char* tessellaVersion() { return TESSELLA_VERSION; }

}  // namespace tessella::sim
