// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/field_output.hpp"

#include "tessella/sim/stages/coupling_stages.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::sim {

FieldSeriesOutput::FieldSeriesOutput(const std::string& directory, std::shared_ptr<const FieldMesh> mesh,
                                     const OutputSpec& spec)
    : writer_(directory, kFieldSeriesName, spec.vtu), mesh_(std::move(mesh)), every_(spec.every) {}

void FieldSeriesOutput::writeIfDue(const Simulation& simulation) {
  const std::size_t step = simulation.clockStep();
  if (!mesh_->hasMesh() || !(step % every_ == 0 || simulation.finished())) return;
  io::MeshFields fields;
  fields.point = mesh_->fields();
  writer_.write(mesh_->mesh(), simulation.time(), fields);
}

std::shared_ptr<const FieldMesh> findFieldMesh(const Simulation& simulation) {
  for (std::size_t i = 0; i < simulation.numStages(); ++i)
    if (const auto* s = dynamic_cast<const MeshFieldStage*>(&simulation.stage(i))) return s->fieldMesh();
  return nullptr;
}

std::shared_ptr<FieldSeriesOutput> attachFieldOutput(Simulation& simulation, const std::string& directory,
                                                     const OutputSpec& spec, std::optional<double> resume_after) {
  auto mesh = findFieldMesh(simulation);
  if (!mesh) return nullptr;
  if (spec.name == kFieldSeriesName)
    throw InputError(std::string("output.name '") + kFieldSeriesName +
                     "' is the solver fields' series name; choose another");
  auto output = std::make_shared<FieldSeriesOutput>(directory, std::move(mesh), spec);
  if (resume_after)
    output->continueAfter(*resume_after);
  else
    output->writeIfDue(simulation);  // the initial state, when a stage set one up
  simulation.onStep([output](const Simulation& s) { output->writeIfDue(s); });
  return output;
}

}  // namespace tessella::sim
