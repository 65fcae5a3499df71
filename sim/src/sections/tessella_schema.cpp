#include "tessella/sim/sections/tessella_schema.hpp"

#include "tessella/sim/sections/coupling_section.hpp"
#include "tessella/sim/sections/growth_section.hpp"
#include "tessella/sim/sections/mesh_section.hpp"
#include "tessella/sim/sections/output_section.hpp"
#include "tessella/sim/sections/time_section.hpp"
#include "tessella/sim/sections/tissue_section.hpp"

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
  declareGrowthSection(s);
  declareDivisionSection(s);
  declareOutputSection(s);
  declareDiffusionSection(s);
  declareCompartmentSection(s);
  declareElasticitySection(s);
  declareMeshSection(s);
  // Extension point: declare new sections here (declareGrowthSection(s); ...).
  return s;
}
}  // namespace

const Schema& tessellaSchema() {
  static const Schema schema = makeSchema();
  return schema;
}

const char* tessellaVersion() { return TESSELLA_VERSION; }

}  // namespace tessella::sim
