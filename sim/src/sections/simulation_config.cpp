// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/simulation_config.hpp"

#include <charconv>
#include <limits>
#include <map>
#include <random>

#include "tessella/sim/config/config_loader.hpp"
#include "tessella/sim/sections/tessella_schema.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/stage.hpp"
#include "tissue_shape_checks.hpp"

namespace tessella::sim {

namespace {
std::uint64_t freshSeed() {
  std::random_device device;
  const std::uint64_t seed = (std::uint64_t{device()} << 32) ^ device();
  return seed & static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());  // fits rng_seed's int
}

// The seed a snapshot's run used, if it recorded one that rng_seed can hold.
bool savedSeed(const io::RunState& state, std::uint64_t& seed) {
  const auto it = state.find("rng_seed");
  if (it == state.end()) return false;
  const std::string& text = it->second;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), seed);
  return result.ec == std::errc() && result.ptr == text.data() + text.size() &&
         seed <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
}
}  // namespace

SimulationConfig readSimulationConfig(Config config) {
  if (config.has("tessella_version") && config.getString("tessella_version") != tessellaVersion())
    config.addNote(config.entry("tessella_version").where.str() + ": this configuration was written by Tessella " +
                   config.getString("tessella_version") + "; this is " + tessellaVersion() +
                   ", so results may differ");
  config.set("tessella_version", std::string(tessellaVersion()), {}, ValueOrigin::Derived);
  TissueSpec tissue = readTissueSection(config);
  auto* snap = std::get_if<SnapshotSpec>(&tissue);
  std::uint64_t seed = 0;
  if (config.has("rng_seed")) {
    seed = static_cast<std::uint64_t>(config.getInt("rng_seed"));
  } else {
    // A restart without a seed of its own continues the snapshot's stream.
    if (!(snap && savedSeed(snap->state, seed))) seed = freshSeed();
    config.set("rng_seed", static_cast<std::int64_t>(seed), {}, ValueOrigin::Derived);
  }
  // A restart continues the snapshot's clock unless the file says otherwise.
  if (snap) {
    const double saved = snap->tissue->time();
    if (!config.isGiven("time.start"))
      config.set("time.start", saved, {}, ValueOrigin::Derived);
    else if (config.getFloat("time.start") != saved)
      config.addNote(config.entry("time.start").where.str() + ": the clock starts at time.start = " +
                     formatValue(config.entry("time.start").value) + ", not at the snapshot's time " +
                     formatValue(saved) + " (leave time.start out to continue the snapshot's clock)");
  }
  TimeSpan time = readTimeSection(config);
  if (snap) {
    try {
      snap->rng_state = continueRunState(snap->state, snap->tissue->time(), seed, time);
    } catch (const InputError& e) {
      throw config.errorAt("tissue.snapshot.file", e.what());
    }
  }
  SimulationConfig result{.config = std::move(config), .rng_seed = seed, .tissue = std::move(tissue), .time = time};
  for (const SectionUnit& unit : sectionUnits())
    if (unit.read) unit.read(result.config, result);
  // Ask the stages the sections make which cell properties they write: two
  // stages writing one property would overwrite each other (a network species
  // named like a diffusion species would even take its values as its state),
  // and a division gate reads a value some stage writes.
  std::vector<std::string> written;
  std::map<std::string, std::string> writer;  // property -> the stage writing it
  for (const auto& stage : makeStages(result)) {
    for (const std::string& name : stage->cellPropertiesWritten()) {
      const auto [it, first] = writer.emplace(name, stage->name());
      if (!first && it->second != stage->name())
        throw result.config.errorAt(stage->name(), "the cell property '" + name + "' is written by both the " +
                                                       it->second + " and the " + stage->name() +
                                                       " stage; give one of them another name");
      written.push_back(name);
    }
  }
  if (result.division.gate) checkDivisionGate(result.config, result.division, written);
  detail::checkTissueShape(result);  // keys that assume a dimension, against the tissue's
  return result;
}

SimulationConfig loadSimulationConfigFile(const std::string& path, const std::vector<std::string>& overrides) {
  return readSimulationConfig(loadConfigFile(path, overrides, tessellaSchema()));
}

SimulationConfig loadSimulationConfigString(const std::string& yaml, const std::vector<std::string>& overrides,
                                            const std::string& base_directory) {
  return readSimulationConfig(
      loadConfigString(yaml, overrides, tessellaSchema(), "simulation", "<string>", base_directory));
}

StageList makeStageList(const SimulationConfig& config) {
  StageList stages(config.config);
  for (const SectionUnit& unit : sectionUnits())
    if (unit.make_stages) unit.make_stages(config, stages);
  return stages;
}

std::vector<std::unique_ptr<Stage>> makeStages(const SimulationConfig& config) {
  return makeStageList(config).release();
}

}  // namespace tessella::sim
