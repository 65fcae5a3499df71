// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// SectionUnit: one YAML section as one unit {declare its keys, read them,
// make its stages}. The table of units (sectionUnits(), simulation_config.hpp)
// is what tessellaSchema(), readSimulationConfig() and makeStages() iterate,
// so a new section is one entry there (docs/extending.md).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/sim/stages/field_mesh.hpp"
#include "tessella/sim/stages/stage.hpp"

namespace tessella::sim {

struct SimulationConfig;

/// The stages of a simulation as the sections add them, in order, and the one
/// FieldMesh the solver stages share: made, with the mesh section's options,
/// by the first stage that asks for it.
class StageList {
 public:
  explicit StageList(const Config& config) : config_(&config) {}
  void add(std::unique_ptr<Stage> stage);
  std::shared_ptr<FieldMesh> fieldMesh();
  /// Whether a stage asked for the FieldMesh (the run then meshes the tissue).
  bool hasFieldMesh() const { return mesh_ != nullptr; }
  const std::vector<std::unique_ptr<Stage>>& stages() const { return stages_; }
  std::vector<std::unique_ptr<Stage>> release() { return std::move(stages_); }

 private:
  const Config* config_;
  std::shared_ptr<FieldMesh> mesh_;
  std::vector<std::unique_ptr<Stage>> stages_;
};

struct SectionUnit {
  std::string name;  ///< the section's key, e.g. "diffusion"
  /// Declares the section and its keys (docs/config.md lists them in the table's order).
  std::function<void(Schema&)> declare;
  /// Reads the section into its member of the SimulationConfig (the frame,
  /// tissue and time, is read already). Empty: nothing to read up front.
  std::function<void(const Config&, SimulationConfig&)> read;
  /// Adds the section's stages; stages run in the table's order. Empty: none.
  std::function<void(const SimulationConfig&, StageList&)> make_stages;
};

}  // namespace tessella::sim
