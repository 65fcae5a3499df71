// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The state of a run's solver fields beside one of its snapshots, so that a
// restart from the snapshot continues them exactly: the finite-element mesh
// the fields live on, the lineage id of every cell its elements lie in, and
// the nodal values by name. One .vtu per snapshot, named after it
// (fieldStatePath: DIR/tissue_000035.vtu -> DIR/tissue_000035.fields.vtu),
// written atomically with every array checksummed like a snapshot's; the
// snapshot's run state names it and records the CRC-32 of its bytes, so that
// a file of another step or run is refused (docs/output.md, "Solver fields
// beside a snapshot").
//
//   points      the mesh nodes (exact doubles)
//   cells       VTK_TRIANGLE (dim 2) | VTK_TETRA (dim 3), the elements in order
//   cell data   cell_id (Int32): FeMesh::element_cell
//   point data  vertex_id (Int32): FeMesh::node_vertex; each field (Float64)
//   field data  tessella_field_state_version, tessella_mesh_dim,
//               tessella_fields (the field names), wall_facets (Int32, dim
//               components), facet_wall (Int32), facet_on_boundary (UInt8),
//               cell_lineage (Int64)

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "tessella/io/vtu.hpp"
#include "tessella/mesh/fe_mesh.hpp"

namespace tessella::io {

struct FieldState {
  mesh::FeMesh mesh;
  /// The lineage id of every cell index FeMesh::element_cell refers to (-1
  /// for an index no cell has).
  std::vector<std::int64_t> cell_lineage;
  /// Nodal values by name (one per mesh node).
  std::map<std::string, Eigen::VectorXd> fields;
};

/// The file beside `snapshot_path` that holds its field state:
/// <directory>/<stem>.fields.vtu.
std::string fieldStatePath(const std::string& snapshot_path);

/// Writes `state` atomically (InputError naming the path when the mesh's
/// arrays, the lineage list or a field's size do not fit, or the file cannot
/// be written); returns fileChecksum() of the file written.
std::uint32_t writeFieldState(const FieldState& state, const std::string& path, const VtuOptions& options = {});

/// Reads a file writeFieldState wrote. InputError starting with the path
/// when it is missing, damaged (an array that does not match its checksum)
/// or not a field state, naming what is wrong.
FieldState readFieldState(const std::string& path);

/// CRC-32 of a file's bytes (InputError naming the path if it cannot be read).
std::uint32_t fileChecksum(const std::string& path);

}  // namespace tessella::io
