#pragma once
// A Simulation from a config: the stages its sections ask for, and the
// definitions of Simulation::fromConfig/fromFile/fromYaml (simulation.hpp
// declares them without knowing the config). Include this header, or
// sections/simulation_config.hpp, to call fromConfig with a SimulationConfig.

#include <memory>
#include <vector>

#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/stage.hpp"

namespace tessella::sim {

/// The stages a config asks for, in execution order (growth, division, then
/// the solver sections).
std::vector<std::unique_ptr<Stage>> makeStages(const SimulationConfig& config);

}  // namespace tessella::sim
