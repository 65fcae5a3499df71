// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/section_unit.hpp"

#include <stdexcept>

#include "tessella/sim/sections/mesh_section.hpp"

namespace tessella::sim {

void StageList::add(std::unique_ptr<Stage> stage) {
  if (!stage) throw std::invalid_argument("StageList::add: null stage");
  stages_.push_back(std::move(stage));
}

std::shared_ptr<FieldMesh> StageList::fieldMesh() {
  if (!mesh_) mesh_ = std::make_shared<FieldMesh>(meshOptionsFromConfig(*config_));
  return mesh_;
}

}  // namespace tessella::sim
