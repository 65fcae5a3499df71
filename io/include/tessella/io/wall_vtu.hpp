// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A tissue's walls as a .vtu of their own, with values per wall: what a
// tissue snapshot cannot show (it holds cells only), such as the PIN on each
// side of each wall or the walls' mechanics (docs/output.md, "Wall data beside
// a snapshot"). The one writer of per-wall data: the network stage's
// <stem>.pin.vtu and the mechanics stage's <stem>.walls.vtu.
//
//   points      the live vertices in slot order (as a snapshot numbers them)
//   cells       VTK_LINE (2D tissues: the wall's edge) | VTK_POLYGON (3D: the wall's loop),
//               one per live wall in slot order
//   cell data   wall_id (Int32, the wall's slot) + each scalar (Float64),
//               vector (Float64, 3 components) and symmetric tensor (Float64,
//               6 components in VTK's order XX YY ZZ XY YZ XZ) array by name
//
// ParaView: Cell Centers, then Glyph oriented by a vector array.

#include <map>
#include <string>
#include <vector>

#include "tessella/io/vtu.hpp"
#include "tessella/tissue/tissue.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::io {

/// Values per wall, one per live wall in slot order.
struct WallArrays {
  std::map<std::string, std::vector<double>> scalars;
  std::map<std::string, std::vector<Vec3>> vectors;
  std::map<std::string, std::vector<Sym3>> tensors;
};

/// The wall property columns of `tissue` named in `names` (double, Vec3 or
/// Sym3) as WallArrays, one value per live wall in slot order. A name the
/// tissue's walls do not have is left out; InputError naming the property
/// when it has another type.
WallArrays wallPropertyArrays(const Tissue& tissue, const std::vector<std::string>& names);

/// The same for the cell property columns of `tissue`: one value per live
/// cell in slot order (the rows of MeshFields::cells; the encoding is the one
/// of wall arrays).
WallArrays cellPropertyArrays(const Tissue& tissue, const std::vector<std::string>& names);

/// The file beside `snapshot_path` named with `tag`: <directory>/<stem>.<tag>.vtu.
std::string besideSnapshotPath(const std::string& snapshot_path, const std::string& tag);

/// Writes the walls of `tissue` with `arrays` atomically; InputError naming
/// the array when its size is not the number of live walls or its name is
/// empty or `wall_id`, and naming the path when the file cannot be written.
void writeWallsVtu(const Tissue& tissue, const std::string& path, const WallArrays& arrays,
                   const VtuOptions& options = {});

/// What a walls file holds: the wall slots and the arrays, and the number of
/// points and of each cell's points (2 for a 2D wall).
struct WallsFile {
  std::vector<int> wall_id;
  std::vector<int> points_per_wall;
  std::size_t points = 0;
  WallArrays arrays;
};

/// Reads a file writeWallsVtu wrote (InputError naming the path when it is
/// missing, damaged or has no wall_id array). Arrays of 1, 3 and 6
/// components come back as scalars, vectors and tensors.
WallsFile readWallsVtu(const std::string& path);

}  // namespace tessella::io
