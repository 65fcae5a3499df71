// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// MeshOutput: with mesh.output on, a run writes the finite-element mesh of the
// tissue as a ParaView series beside the tissue series: DIR/mesh.pvd listing
// DIR/mesh_NNNNNN.vtu (elements with cell_id) and DIR/mesh_walls.pvd (wall
// facets with wall_id and the stages' values per wall, Stage::meshWallArrays:
// a mechanics run's walls-file arrays on each wall's facets; the elements carry
// the stages' values per cell, Stage::meshCellArrays: a curved sheet's membrane
// outputs on each cell's elements), on the schedule of SeriesOutput (initial state, every
// mesh.every steps, final state). The mesh is rebuilt only when the tissue's
// topology or geometry version moved since the last mesh.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "tessella/io/mesh_vtu.hpp"
#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/sim/sections/mesh_section.hpp"
#include "tessella/sim/sections/output_section.hpp"
#include "tessella/sim/simulation.hpp"

namespace tessella::sim {

class MeshOutput {
 public:
  /// `every` is the resolved schedule (mesh.every, else output.every).
  MeshOutput(const std::string& directory, const MeshSpec& spec, std::size_t every, const io::VtuOptions& vtu);

  /// Writes the mesh of the current state if due at the simulation's step.
  void writeIfDue(const Simulation& simulation);
  /// Writes it now (once per step: a second call is a no-op).
  void write(const Simulation& simulation);
  /// Continues the series on disk after `time` (io::MeshSeriesWriter::continueAfter).
  void continueAfter(const Simulation& simulation, double time);

  std::size_t snapshots() const { return writer_.steps(); }
  /// How many times the tissue was meshed (<= snapshots()).
  std::size_t meshes() const { return meshes_; }
  const std::string& pvdPath() const { return writer_.pvdPath(); }

 private:
  io::MeshSeriesWriter writer_;
  mesh::MeshOptions options_;
  std::size_t every_;
  std::optional<mesh::FeMesh> mesh_;
  std::uint64_t topology_ = 0, geometry_ = 0;
  std::size_t meshes_ = 0;
  std::size_t last_written_step_ = static_cast<std::size_t>(-1);
};

/// With spec.output: writes the current state's mesh now and registers a step
/// callback that keeps the series up to date; returns null otherwise.
/// `resume_after` as for attachSeriesOutput.
std::shared_ptr<MeshOutput> attachMeshOutput(Simulation& simulation, const std::string& directory,
                                             const MeshSpec& spec, const OutputSpec& output,
                                             std::optional<double> resume_after = std::nullopt);

}  // namespace tessella::sim
