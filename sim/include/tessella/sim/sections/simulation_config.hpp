#pragma once
// SimulationConfig: a validated Config read into typed parameter structs,
// one per section. What a Simulation and a run are built from.

#include <cstdint>
#include <string>
#include <vector>

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/sections/coupling_section.hpp"
#include "tessella/sim/sections/growth_section.hpp"
#include "tessella/sim/sections/output_section.hpp"
#include "tessella/sim/sections/time_section.hpp"
#include "tessella/sim/sections/tissue_section.hpp"

namespace tessella::sim {

struct SimulationConfig {
  /// The resolved keys, including derived values (the RNG seed actually
  /// used): the source of run.yaml.
  Config config;
  /// Seed of every random draw of the run. Given by `rng_seed`, or drawn
  /// from std::random_device and recorded in `config`.
  std::uint64_t rng_seed = 0;
  TissueSpec tissue;
  TimeSpan time;
  OutputSpec output;
  GrowthSpec growth;
  DivisionSpec division;
  DiffusionSpec diffusion;
  CompartmentSpec compartments;
  ElasticitySpec elasticity;
  // Extension point: one member per new section (GrowthSpec growth; ...),
  // filled in readSimulationConfig().
};

/// Reads every section of a validated Config (cross-key checks included).
SimulationConfig readSimulationConfig(Config config);

/// loadConfigFile()/loadConfigString() with the Tessella schema, then
/// readSimulationConfig(). Throws ConfigError; nothing is written.
SimulationConfig loadSimulationConfigFile(const std::string& path,
                                          const std::vector<std::string>& overrides = {});
SimulationConfig loadSimulationConfigString(const std::string& yaml,
                                            const std::vector<std::string>& overrides = {},
                                            const std::string& base_directory = ".");

}  // namespace tessella::sim
