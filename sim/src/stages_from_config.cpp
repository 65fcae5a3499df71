#include "tessella/sim/growth_stages.hpp"
#include "tessella/sim/simulation.hpp"

namespace tessella::sim {

// Extension point: turn config sections into stages, in execution order,
// e.g. growth (move vertices) then division (split cells over a threshold):
//   stages.push_back(makeGrowthStage(config.growth));
std::vector<std::unique_ptr<Stage>> makeStages(const SimulationConfig& config) {
  std::vector<std::unique_ptr<Stage>> stages;
  if (config.growth.field) stages.push_back(std::make_unique<GrowthStage>(config.growth));
  if (config.division.rule) stages.push_back(std::make_unique<DivisionStage>(config.division));
  return stages;
}

}  // namespace tessella::sim
