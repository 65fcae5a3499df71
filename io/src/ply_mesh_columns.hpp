// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The columns every PLY mesh importer reads the same way (MorphoGraphX,
// cell complexes, labelled meshes): vertex positions and the faces' vertex
// lists, checked, with errors naming the file and the element.

#include <string>
#include <vector>

#include "tessella/io/ply.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::io::detail {

/// The vertex element's x, y, z; InputError naming the file and the vertex
/// when a position is not finite.
std::vector<Vec3> plyPositions(const PlyFile& ply, const std::string& path);

/// The face element's vertex list (`vertex_indices`, else `vertex_index`),
/// of an integer type; InputError naming the file otherwise.
const PlyColumn& plyFaceVertexList(const PlyFile& ply, const std::string& path);

}  // namespace tessella::io::detail
