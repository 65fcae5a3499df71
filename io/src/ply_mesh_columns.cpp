// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ply_mesh_columns.hpp"

#include "labelled_surface.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::io::detail {

std::vector<Vec3> plyPositions(const PlyFile& ply, const std::string& path) {
  const std::size_t nv = ply.count("vertex");
  const PlyColumn& x = ply.scalar("vertex", "x");
  const PlyColumn& y = ply.scalar("vertex", "y");
  const PlyColumn& z = ply.scalar("vertex", "z");
  std::vector<Vec3> positions(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    positions[i] = Vec3(x.values[i], y.values[i], z.values[i]);
    if (!positions[i].allFinite())
      throw InputError("'" + path + "' vertex " + std::to_string(i) + ": position " + fmtPoint(positions[i]) +
                       " is not finite");
  }
  return positions;
}

const PlyColumn& plyFaceVertexList(const PlyFile& ply, const std::string& path) {
  const char* list_name = ply.hasProperty("face", "vertex_indices") ? "vertex_indices" : "vertex_index";
  if (!ply.hasProperty("face", list_name))
    throw InputError("'" + path + "': element 'face' has no vertex list (property 'vertex_indices' or "
                     "'vertex_index')");
  const PlyColumn& fv = ply.list("face", list_name);
  if (fv.type == PlyType::Float32 || fv.type == PlyType::Float64)
    throw InputError("'" + path + "': face property '" + list_name + "' holds " + plyTypeName(fv.type) +
                     " values, expected vertex indices of an integer type");
  return fv;
}

}  // namespace tessella::io::detail
