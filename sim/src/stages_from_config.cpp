#include "tessella/sim/simulation.hpp"

namespace tessella::sim {

// Extension point: turn config sections into stages, in execution order,
// e.g. growth (move vertices) then division (split cells over a threshold):
//   stages.push_back(makeGrowthStage(config.growth));
std::vector<std::unique_ptr<Stage>> makeStages(const SimulationConfig& /*config*/) {
  return {};
}

}  // namespace tessella::sim
