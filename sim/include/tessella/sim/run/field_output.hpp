// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// FieldSeriesOutput: writes the solver stages' mesh (the shared FieldMesh)
// with its nodal fields as point data (a diffusing species, displacements) as
// a ParaView mesh series DIR/fields.pvd + DIR/fields_NNNNNN.vtu (and the wall
// facets as DIR/fields_walls.pvd), on the tissue series' schedule. Cell data
// (cell averages, stresses) are in the tissue series, as cell properties.
// Nothing is written while there is no mesh yet (before the first solve of a
// steady species or of elasticity; a transient species is meshed at the start).

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "tessella/io/mesh_vtu.hpp"
#include "tessella/sim/sections/output_section.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/field_mesh.hpp"

namespace tessella::sim {

/// Series name of the field output.
inline constexpr const char* kFieldSeriesName = "fields";

class FieldSeriesOutput {
 public:
  FieldSeriesOutput(const std::string& directory, std::shared_ptr<const FieldMesh> mesh, const OutputSpec& spec);
  /// Writes the mesh and its fields if due at the simulation's step and solved at least once.
  void writeIfDue(const Simulation& simulation);
  /// Continues the series on disk after `time` (io::MeshSeriesWriter::continueAfter).
  void continueAfter(double time) { writer_.continueAfter(time); }
  std::size_t snapshots() const { return writer_.steps(); }
  const std::string& pvdPath() const { return writer_.pvdPath(); }

 private:
  io::MeshSeriesWriter writer_;
  std::shared_ptr<const FieldMesh> mesh_;
  std::size_t every_;
};

/// The FieldMesh the simulation's solver stages share, or null when none has one.
std::shared_ptr<const FieldMesh> findFieldMesh(const Simulation& simulation);

/// Registers a step callback writing the field series when the simulation
/// has solver stages with a mesh; returns null (and registers nothing) otherwise.
/// `resume_after` as for attachSeriesOutput.
std::shared_ptr<FieldSeriesOutput> attachFieldOutput(Simulation& simulation, const std::string& directory,
                                                     const OutputSpec& spec,
                                                     std::optional<double> resume_after = std::nullopt);

}  // namespace tessella::sim
