// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// WallArrays as VTK cell data: the one encoding of values per wall, used by
// the walls file beside a snapshot (one VTK cell per wall) and by the wall
// facets of a mesh series (several facets per wall).

#include <cstddef>
#include <vector>

#include "tessella/io/wall_vtu.hpp"

class vtkCellData;

namespace tessella::io::detail {

/// Adds every array of `arrays` to `data` as Float64: scalars with one
/// component, vectors with 3, symmetric tensors with 6 in VTK's order XX YY ZZ
/// XY YZ XZ. VTK cell i gets row `rows[i]` of each array (rows in range).
void addWallArrays(vtkCellData* data, const WallArrays& arrays, const std::vector<std::size_t>& rows);

}  // namespace tessella::io::detail
