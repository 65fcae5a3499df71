// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Finite-element meshes (tessella::mesh::FeMesh) as .vtu files, for looking at the
// fields a solver computed: the elements (triangles or tetrahedra) with the
// tissue cell of each element, and, as a second file, the wall facets
// (segments or triangles) with the tissue wall of each facet.
//
//   elements file     cells: VTK_TRIANGLE (dim 2) | VTK_TETRA (dim 3)
//                     cell data  cell_id (Int32) + MeshFields::element
//                                + MeshFields::cells (each element its tissue cell's values)
//                     point data vertex_id (Int32, -1 for mesher nodes) + MeshFields::point
//   wall facets file  cells: VTK_LINE (dim 2) | VTK_TRIANGLE (dim 3), same points
//                     cell data  wall_id (Int32), on_boundary (UInt8) + MeshFields::facet
//                                + MeshFields::walls (each facet its wall's values, as in a walls file)
//                     point data as the elements file
//
// Both files are written atomically with the same options as tissue snapshots.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "tessella/io/vtu.hpp"
#include "tessella/io/wall_vtu.hpp"
#include "tessella/mesh/fe_mesh.hpp"

namespace tessella::io {

/// Named scalar fields to write with a mesh (e.g. a concentration per node).
struct MeshFields {
  std::map<std::string, Eigen::VectorXd> point;    ///< one value per node
  std::map<std::string, Eigen::VectorXd> element;  ///< one value per element
  std::map<std::string, Eigen::VectorXd> facet;    ///< one value per wall facet
  /// Values per tissue wall (scalars, vectors, symmetric tensors: what a walls
  /// file beside a snapshot holds, wall_vtu.hpp), written on every wall facet
  /// of that wall (FeMesh::facet_wall), so ParaView can glyph them on the mesh.
  /// Row i of every array belongs to the wall slot wall_ids[i] (io::wallPropertyArrays
  /// gives the live walls in slot order).
  WallArrays walls{};
  std::vector<int> wall_ids{};
  /// Values per tissue cell in the same encoding (io::cellPropertyArrays: a
  /// curved sheet's membrane tensions, strains, pressure...), written on every
  /// element of that cell (FeMesh::element_cell). Row i belongs to the cell
  /// slot cell_ids[i].
  WallArrays cells{};
  std::vector<int> cell_ids{};
};

/// Checks the mesh's arrays agree (row widths, sizes, node indices in range)
/// and the fields' sizes; InputError naming the array or field, its size and
/// the expected one, a wall array with an empty or reserved name (wall_id,
/// on_boundary, a facet field's), or a wall facet whose wall has no row in
/// fields.walls; the same for a cell array (reserved: cell_id, an element
/// field's) and an element whose cell has no row in fields.cells. Called by both writers before anything is written.
void checkFeMesh(const mesh::FeMesh& mesh, const MeshFields& fields = {});

void writeFeMeshVtu(const mesh::FeMesh& mesh, const std::string& path, const MeshFields& fields = {},
                    const VtuOptions& options = {});
void writeWallFacetsVtu(const mesh::FeMesh& mesh, const std::string& path, const MeshFields& fields = {},
                        const VtuOptions& options = {});

/// What an elements file holds besides its geometry: each element's cell_id
/// and every other cell array (MeshFields::element fields and MeshFields::cells
/// rows) as scalars, vectors or tensors, one value per element.
struct FeMeshElementsFile {
  std::vector<int> cell_id;
  WallArrays arrays;
};

/// Reads the cell data of a file writeFeMeshVtu wrote (InputError naming the
/// path when it is missing, damaged or has no cell_id array).
FeMeshElementsFile readFeMeshElementsVtu(const std::string& path);

/// Time series of meshes with the conventions of SeriesWriter: DIR/<name>.pvd
/// lists DIR/<name>_000000.vtu, ... and DIR/<name>_walls.pvd lists
/// DIR/<name>_walls_000000.vtu, ...; both .pvd files are rewritten
/// atomically after every step.
class MeshSeriesWriter {
 public:
  MeshSeriesWriter(std::string directory, std::string name = "mesh", VtuOptions options = {});

  /// Writes both files of one step; returns the elements file's path.
  std::string write(const mesh::FeMesh& mesh, double time, const MeshFields& fields = {});

  const std::string& pvdPath() const { return pvd_path_; }
  const std::string& wallsPvdPath() const { return walls_pvd_path_; }
  /// Continues the series on disk, as SeriesWriter::continueAfter (both .pvd files).
  void continueAfter(double last_time);
  std::size_t steps() const { return times_.size(); }

 private:
  std::string directory_;
  std::string name_;
  std::string pvd_path_;
  std::string walls_pvd_path_;
  VtuOptions options_;
  std::vector<double> times_;
};

}  // namespace tessella::io
