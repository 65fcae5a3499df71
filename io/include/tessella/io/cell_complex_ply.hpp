// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Writing a tissue as a cell-complex PLY file (the "property topomesh" layout
// of the OpenAlea cellcomplex tools), which importCellComplex reads back
// (docs/import.md).
//
//   vertex  x y z (double)
//   face    vertex_index (list int int): a wall (3D) or a cell's polygon (2D),
//           its loop as the tissue stores it
//   edge    source target (int)
//   volume  face_index (list int int, 0-based, as OpenAlea's
//           save_ply_property_topomesh writes it), label (int)
//
// A 3D tissue gives closed volumes sharing their walls; a 2D tissue (planar or
// curved sheet) one volume per cell listing its one polygon, an open patch.

#include <cstddef>
#include <string>

#include "tessella/tissue/tissue.hpp"

namespace tessella::io {

struct CellComplexPlyOptions {
  /// binary_little_endian instead of ASCII (OpenAlea's own reader reads
  /// ASCII only). Both keep every coordinate exactly.
  bool binary = false;
};

struct CellComplexPlyInfo {
  std::size_t vertices = 0, edges = 0, faces = 0, volumes = 0;
  /// Where the volume labels come from: "label" (the tissue's int64 cell
  /// property `label`, when every live cell has its own) or "lineage_id".
  std::string label_source;
};

/// Writes `tissue` to `path` atomically (no file on error). InputError naming
/// the cell when a label does not fit the file's 32-bit int, and for a path
/// that cannot be written.
CellComplexPlyInfo writeCellComplexPly(const Tissue& tissue, const std::string& path,
                                       const CellComplexPlyOptions& options = {});

}  // namespace tessella::io
