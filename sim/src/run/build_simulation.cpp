// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// A Simulation from a config (simulation.hpp declares these without knowing
// the config): the tissue its generator describes and the stages its
// sections make.

#include <optional>
#include <variant>

#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/sim/simulation.hpp"

namespace tessella::sim {

namespace {
// A mesh the size bounds make too large is refused before the stages start,
// not at the first solve (after output began); named at the size key.
void checkMeshSize(const Config& c, const Tissue& tissue, bool meshed_by_stages) {
  if (!meshed_by_stages && !c.getBool("mesh.output")) return;
  const mesh::MeshOptions o = meshOptionsFromConfig(c);
  try {
    mesh::checkElementLimit(tissue, o);
  } catch (const InputError& e) {
    const bool by_volume = tissue.dim() == 3 && o.max_volume > 0 &&
                           (o.max_edge_length == 0 || o.volume_method == mesh::VolumeMethod::WholeTissue);
    throw c.errorAt(by_volume ? "mesh.max_volume" : "mesh.max_edge_length", e.what());
  }
}
}  // namespace

Simulation Simulation::fromConfig(const SimulationConfig& config) {
  SimulationOptions options{.time = config.time, .rng_seed = config.rng_seed, .rng_state = {}, .carried = {}};
  if (const auto* snapshot = std::get_if<SnapshotSpec>(&config.tissue)) options.rng_state = snapshot->rng_state;
  if (const std::optional<Dome> dome = tissueDome(config.tissue)) options.carried = domeRunState(*dome);
  Simulation sim(buildTissue(config.tissue, config.rng_seed, config.config), options);
  StageList stages = makeStageList(config);
  checkMeshSize(config.config, sim.tissue(), stages.hasFieldMesh());
  const auto* snapshot = std::get_if<SnapshotSpec>(&config.tissue);
  for (auto& stage : stages.release()) {
    if (snapshot) stage->continueFrom(snapshot->file, snapshot->state);  // before prepare()
    sim.addStage(std::move(stage));
  }
  return sim;
}

Simulation Simulation::fromFile(const std::string& path, const std::vector<std::string>& overrides) {
  return fromConfig(loadSimulationConfigFile(path, overrides));
}

Simulation Simulation::fromYaml(const std::string& yaml, const std::vector<std::string>& overrides,
                                const std::string& base_directory) {
  return fromConfig(loadSimulationConfigString(yaml, overrides, base_directory));
}

}  // namespace tessella::sim
