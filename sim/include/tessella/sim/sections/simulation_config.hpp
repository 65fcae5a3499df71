// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// SimulationConfig: a validated Config read into typed parameter structs,
// one per section. What a Simulation and a run are built from.
//
// Every section but the frame (tissue and time, read first: a restart's
// snapshot decides the defaults of the seed and the clock) is a unit in
// sectionUnits() below, which the schema, the reader and makeStages() iterate.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/sections/coupling_section.hpp"
#include "tessella/sim/sections/growth_section.hpp"
#include "tessella/sim/sections/mechanics_section.hpp"
#include "tessella/sim/sections/mesh_section.hpp"
#include "tessella/sim/sections/network_section.hpp"
#include "tessella/sim/sections/output_section.hpp"
#include "tessella/sim/sections/section_unit.hpp"
#include "tessella/sim/sections/time_section.hpp"
#include "tessella/sim/sections/tissue_section.hpp"
#include "tessella/sim/stages/stage.hpp"

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
  // One member per section unit (filled by its `read`):
  OutputSpec output;
  GrowthSpec growth;
  DivisionSpec division;
  MechanicsSpec mechanics;
  DiffusionSpec diffusion;
  CompartmentSpec compartments;
  ElasticitySpec elasticity;
  NetworkSpec network;
};

/// The sections after the frame, in the order of their keys in docs/config.md
/// and of their stages in a step: growth, division, mechanics (turgor-driven
/// growth), then the solvers (which share the mesh the mesh section describes).
inline const std::vector<SectionUnit>& sectionUnits() {
  using S = SimulationConfig;
  static const std::vector<SectionUnit> units = {
      {"growth", declareGrowthSection, [](const Config& c, S& s) { s.growth = readGrowthSection(c, s.tissue); },
       [](const S& s, StageList& stages) { addGrowthStage(s.growth, stages); }},
      {"division", declareDivisionSection, [](const Config& c, S& s) { s.division = readDivisionSection(c); },
       [](const S& s, StageList& stages) { addDivisionStage(s.division, stages); }},
      {"mechanics", declareMechanicsSection, [](const Config& c, S& s) { s.mechanics = readMechanicsSection(c); },
       [](const S& s, StageList& stages) { addMechanicsStage(s.mechanics, stages); }},
      {"output", declareOutputSection, [](const Config& c, S& s) { s.output = readOutputSection(c); }, {}},
      {"diffusion", declareDiffusionSection, [](const Config& c, S& s) { s.diffusion = readDiffusionSection(c); },
       [](const S& s, StageList& stages) { addDiffusionStage(s.diffusion, stages); }},
      {"elasticity", declareElasticitySection,
       [](const Config& c, S& s) { s.elasticity = readElasticitySection(c); },
       [](const S& s, StageList& stages) { addElasticityStage(s.elasticity, stages); }},
      {"compartments", declareCompartmentSection,
       [](const Config& c, S& s) { s.compartments = readCompartmentSection(c); },
       [](const S& s, StageList& stages) { addCompartmentStage(s.compartments, stages); }},
      {"network", declareNetworkSection,
       [](const Config& c, S& s) { s.network = readNetworkSection(c, s.rng_seed); },
       [](const S& s, StageList& stages) { addNetworkStage(s.network, stages); }},
      // Read on demand (meshOptionsFromConfig, readMeshSection) by the stages and the run.
      {"mesh", declareMeshSection, {}, {}},
  };
  return units;
}

/// Reads every section of a validated Config (cross-key checks included).
SimulationConfig readSimulationConfig(Config config);

/// loadConfigFile()/loadConfigString() with the Tessella schema, then
/// readSimulationConfig(). Throws ConfigError; nothing is written.
SimulationConfig loadSimulationConfigFile(const std::string& path,
                                          const std::vector<std::string>& overrides = {});
SimulationConfig loadSimulationConfigString(const std::string& yaml,
                                            const std::vector<std::string>& overrides = {},
                                            const std::string& base_directory = ".");

/// The stages the sections of `config` ask for, in the table's order.
StageList makeStageList(const SimulationConfig& config);
std::vector<std::unique_ptr<Stage>> makeStages(const SimulationConfig& config);

}  // namespace tessella::sim
