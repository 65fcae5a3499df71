// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A tissue's walls as a .vtu of their own, with values per wall: what a
// tissue snapshot cannot show (it holds cells only), such as the PIN on each
// side of each wall (docs/output.md, "Wall data beside a snapshot").
//
//   points      the live vertices in slot order (as a snapshot numbers them)
//   cells       VTK_LINE (2D tissues: the wall's edge) | VTK_POLYGON (3D: the wall's loop),
//               one per live wall in slot order
//   cell data   wall_id (Int32, the wall's slot) + each scalar (Float64) and
//               vector (Float64, 3 components) array by name
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
};

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
/// missing, damaged or has no wall_id array).
WallsFile readWallsVtu(const std::string& path);

}  // namespace tessella::io
