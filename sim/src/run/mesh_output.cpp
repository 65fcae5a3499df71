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
  // The stages' values per wall (a membranes run's tension, strain, fibre...) on each wall's facets.
  io::MeshFields fields;
  for (std::size_t i = 0; i < simulation.numStages(); ++i) {
    io::WallArrays a = simulation.stage(i).meshWallArrays(tissue);
    fields.walls.scalars.merge(a.scalars);
    fields.walls.vectors.merge(a.vectors);
    fields.walls.tensors.merge(a.tensors);
  }
  for (WallId w : tissue.walls()) fields.wall_ids.push_back(static_cast<int>(w.index()));
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
