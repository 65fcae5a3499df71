// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The `mesh:` section: the size and quality targets of the finite-element
// mesh of the tissue (mesh::MeshOptions) and whether a run writes that mesh
// as its own ParaView series (DIR/mesh.pvd beside the tissue series).
// Range checks live in the schema and in validateMeshOptions, so every bad
// value is a ConfigError at its key.

#include <cstddef>
#include <string>
#include <vector>

#include "tessella/mesh/mesh_options.hpp"
#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"

namespace tessella::sim {

struct MeshSpec {
  mesh::MeshOptions options;
  /// Write the mesh series DIR/<name>.pvd + DIR/<name>_NNNNNN.vtu during a run.
  bool output = false;
  /// Series name of the mesh output.
  std::string name = "mesh";
  /// A mesh snapshot every `every` steps (plus the initial and final states);
  /// 0 = the tissue series' output.every.
  std::size_t every = 0;
};

void declareMeshSection(Schema& schema);
/// Reads mesh.*; out-of-range options are ConfigErrors naming the key.
MeshSpec readMeshSection(const Config& config);
/// The MeshOptions part of the section (for stages that mesh the tissue).
mesh::MeshOptions meshOptionsFromConfig(const Config& config);

}  // namespace tessella::sim
