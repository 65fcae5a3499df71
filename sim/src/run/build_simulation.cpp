#include "tessella/sim/run/build_simulation.hpp"

#include <optional>
#include <variant>

#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/sim/sections/mesh_section.hpp"
#include "tessella/sim/stages/coupling_stages.hpp"
#include "tessella/sim/stages/growth_stages.hpp"

namespace tessella::sim {

// Extension point: turn config sections into stages, in execution order,
// e.g. growth (move vertices) then division (split cells over a threshold):
//   stages.push_back(makeGrowthStage(config.growth));
std::vector<std::unique_ptr<Stage>> makeStages(const SimulationConfig& config) {
  std::vector<std::unique_ptr<Stage>> stages;
  if (config.growth.field) stages.push_back(std::make_unique<GrowthStage>(config.growth.field, config.growth.options));
  if (config.division.rule)
    stages.push_back(std::make_unique<DivisionStage>(config.division.rule, *config.division.threshold,
                                                     config.division.options, config.division.gate));
  // The solvers run after growth and division, on one shared mesh of the tissue.
  if (!config.diffusion.species.empty() || config.elasticity.enabled) {
    auto mesh = std::make_shared<FieldMesh>(meshOptionsFromConfig(config.config));
    if (!config.diffusion.species.empty()) stages.push_back(std::make_unique<DiffusionStage>(config.diffusion, mesh));
    if (config.elasticity.enabled) stages.push_back(std::make_unique<ElasticityStage>(config.elasticity, mesh));
  }
  if (!config.compartments.field.empty()) stages.push_back(std::make_unique<CompartmentStage>(config.compartments));
  return stages;
}

namespace {
// A mesh the size bounds make too large is refused before the stages start,
// not at the first solve (after output began); named at the size key.
void checkMeshSize(const SimulationConfig& config, const Tissue& tissue) {
  const Config& c = config.config;
  if (config.diffusion.species.empty() && !config.elasticity.enabled && !c.getBool("mesh.output")) return;
  const MeshOptions o = meshOptionsFromConfig(c);
  try {
    checkElementLimit(tissue, o);
  } catch (const InputError& e) {
    const bool by_volume = tissue.dim() == 3 && o.max_volume > 0 &&
                           (o.max_edge_length == 0 || o.volume_method == VolumeMethod::WholeTissue);
    throw c.errorAt(by_volume ? "mesh.max_volume" : "mesh.max_edge_length", e.what());
  }
}
}  // namespace

Simulation Simulation::fromConfig(const SimulationConfig& config) {
  SimulationParameters parameters{config.time, config.rng_seed, {}, {}};
  if (const auto* snapshot = std::get_if<SnapshotSpec>(&config.tissue)) parameters.rng_state = snapshot->rng_state;
  if (const std::optional<Dome> dome = tissueDome(config.tissue)) parameters.carried = domeRunState(*dome);
  Simulation sim(buildTissue(config.tissue, config.rng_seed, config.config), parameters);
  checkMeshSize(config, sim.tissue());
  for (auto& stage : makeStages(config)) sim.addStage(std::move(stage));
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
