// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// WallArrays as VTK cell data: the one encoding of values per wall or per
// cell, used by the walls file beside a snapshot (one VTK cell per wall), by
// the wall facets of a mesh series (several facets per wall) and by its
// elements (several elements per tissue cell).

#include <cstddef>
#include <string>
#include <vector>

#include <vtkType.h>

#include "tessella/io/wall_vtu.hpp"

class vtkCellData;

namespace tessella::io::detail {

/// Adds every array of `arrays` to `data` as Float64: scalars with one
/// component, vectors with 3, symmetric tensors with 6 in VTK's order XX YY ZZ
/// XY YZ XZ. VTK cell i gets row `rows[i]` of each array (rows in range).
void addWallArrays(vtkCellData* data, const WallArrays& arrays, const std::vector<std::size_t>& rows);

/// The inverse: every array of `data` but `skip` (the file's id array) with
/// 1, 3 or 6 components as scalars, vectors or tensors (Sym3's order). Each
/// must have `cells` tuples: InputError naming `path`, the array and its size
/// ("... values for <cells> <items>") otherwise.
WallArrays readWallArrays(vtkCellData* data, vtkIdType cells, const std::string& skip, const std::string& path,
                          const std::string& items);

}  // namespace tessella::io::detail
