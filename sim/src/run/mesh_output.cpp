// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/mesh_output.hpp"

#include "tessella/mesh/mesh_tissue.hpp"

namespace tessella::sim {

MeshOutput::MeshOutput(const std::string& directory, const MeshSpec& spec, std::size_t every,
                       const io::VtuOptions& vtu)
    : writer_(directory, spec.name, vtu), options_(spec.options), every_(every) {}

void MeshOutput::writeIfDue(const Simulation& simulation) {
  if (simulation.clockStep() % every_ == 0 || simulation.finished()) write(simulation);
}

void MeshOutput::write(const Simulation& simulation) {
  if (simulation.stepsDone() == last_written_step_) return;
  const Tissue& tissue = simulation.tissue();
  // Meshing is the expensive part: only when the tissue moved or changed shape.
  if (!mesh_ || tissue.topologyVersion() != topology_ || tissue.geometryVersion() != geometry_) {
    mesh_ = mesh::meshTissue(tissue, options_);
    topology_ = tissue.topologyVersion();
    geometry_ = tissue.geometryVersion();
    ++meshes_;
  }
  // The stages' values per wall (a membranes run's tension, strain, fibre...) on each wall's facets, and
  // per cell (a curved sheet's membranes are its cells) on each cell's elements.
  io::MeshFields fields;
  auto merge = [](io::WallArrays& into, io::WallArrays a) {
    into.scalars.merge(a.scalars);
    into.vectors.merge(a.vectors);
    into.tensors.merge(a.tensors);
  };
  for (std::size_t i = 0; i < simulation.numStages(); ++i) {
    merge(fields.walls, simulation.stage(i).meshWallArrays(tissue));
    merge(fields.cells, simulation.stage(i).meshCellArrays(tissue));
  }
  for (WallId w : tissue.walls()) fields.wall_ids.push_back(static_cast<int>(w.index()));
  for (CellId c : tissue.cells()) fields.cell_ids.push_back(static_cast<int>(c.index()));
  writer_.write(*mesh_, simulation.time(), fields);
  last_written_step_ = simulation.stepsDone();
}

void MeshOutput::continueAfter(const Simulation& simulation, double time) {
  writer_.continueAfter(time);
  last_written_step_ = simulation.stepsDone();
}

std::shared_ptr<MeshOutput> attachMeshOutput(Simulation& simulation, const std::string& directory,
                                             const MeshSpec& spec, const OutputSpec& output,
                                             std::optional<double> resume_after) {
  if (!spec.output) return nullptr;
  auto mesh_output =
      std::make_shared<MeshOutput>(directory, spec, spec.every > 0 ? spec.every : output.every, output.vtu);
  if (resume_after)
    mesh_output->continueAfter(simulation, *resume_after);
  else
    mesh_output->write(simulation);
  simulation.onStep([mesh_output](const Simulation& s) { mesh_output->writeIfDue(s); });
  return mesh_output;
}

}  // namespace tessella::sim
