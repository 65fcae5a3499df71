#include "tessella/sim/sections/mesh_section.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/coupling_stages.hpp"
#include "tessella/sim/stages/growth_stages.hpp"

namespace tessella::sim {

// Extension point: turn config sections into stages, in execution order,
// e.g. growth (move vertices) then division (split cells over a threshold):
//   stages.push_back(makeGrowthStage(config.growth));
std::vector<std::unique_ptr<Stage>> makeStages(const SimulationConfig& config) {
  std::vector<std::unique_ptr<Stage>> stages;
  if (config.growth.field) stages.push_back(std::make_unique<GrowthStage>(config.growth));
  if (config.division.rule) stages.push_back(std::make_unique<DivisionStage>(config.division));
  // The solvers run after growth and division, on one shared mesh of the tissue.
  if (!config.diffusion.species.empty() || config.elasticity.enabled) {
    auto mesh = std::make_shared<FieldMesh>(meshOptionsFromConfig(config.config));
    if (!config.diffusion.species.empty()) stages.push_back(std::make_unique<DiffusionStage>(config.diffusion, mesh));
    if (config.elasticity.enabled) stages.push_back(std::make_unique<ElasticityStage>(config.elasticity, mesh));
  }
  if (!config.compartments.field.empty()) stages.push_back(std::make_unique<CompartmentStage>(config.compartments));
  return stages;
}

}  // namespace tessella::sim
