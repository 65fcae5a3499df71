// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Copies the wall segments a 2D mesher collected into FeMesh's wall-facet
// arrays (shared by the planar and the surface mesher; internal).

#include <array>
#include <vector>

#include "tessella/mesh/fe_mesh.hpp"

namespace tessella::mesh::detail {

/// segments: (node a, node b, wall id); on_boundary: one flag per segment.
inline void storeWallSegments(FeMesh& mesh, const std::vector<std::array<int, 3>>& segments,
                              const std::vector<bool>& on_boundary) {
  const auto n = static_cast<Eigen::Index>(segments.size());
  mesh.wall_facets.resize(n, 2);
  mesh.facet_wall.resize(n);
  mesh.facet_on_boundary.resize(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const auto& s = segments[static_cast<std::size_t>(r)];
    mesh.wall_facets.row(r) << s[0], s[1];
    mesh.facet_wall(r) = s[2];
    mesh.facet_on_boundary(r) = on_boundary[static_cast<std::size_t>(r)];
  }
}

}  // namespace tessella::mesh::detail
