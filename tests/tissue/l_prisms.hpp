// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Two prisms stacked over an L-shaped hexagon (a non-convex outline whose
// vertex mean lies on its reflex corner): the wall between them folds as a
// fan from the vertex mean, and bending it makes it non-planar too. Shared by
// the tissue tests (its measures) and the mesh tests (its meshing).

#include <cmath>
#include <vector>

#include "tessella/tissue/builders.hpp"

namespace tessella::fixtures {

inline const std::vector<Vec3> kLShape{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};

struct StackedPrisms {
  std::vector<Vec3> positions;  ///< the L at z = 0, h (the middle wall, vertices 6..11) and 2h
  std::vector<std::vector<Index>> faces;
  std::vector<std::vector<CellFace>> cells;
  Tissue build() const { return buildPolyhedralTissue(positions, faces, cells); }
};

/// Each prism has height h; the middle wall is raised by bend * sin(x + 2y)
/// (bend 0: flat, and the volumes and centroids are exact).
inline StackedPrisms stackedLPrisms(double h, double bend) {
  StackedPrisms s;
  for (double z : {0.0, h, 2 * h})
    for (const Vec3& v : kLShape) s.positions.push_back(v + Vec3(0, 0, z));
  for (int i = 6; i < 12; ++i) s.positions[i].z() += bend * std::sin(s.positions[i].x() + 2 * s.positions[i].y());
  s.faces = {{5, 4, 3, 2, 1, 0}, {6, 7, 8, 9, 10, 11}, {12, 13, 14, 15, 16, 17}};
  s.cells.resize(2);
  s.cells[0] = {{0, false}, {1, false}};
  s.cells[1] = {{1, true}, {2, false}};
  for (Index layer = 0; layer < 2; ++layer)
    for (Index i = 0; i < 6; ++i) {
      const Index a = 6 * layer + i, b = 6 * layer + (i + 1) % 6;
      s.cells[layer].push_back({static_cast<Index>(s.faces.size()), false});
      s.faces.push_back({a, b, b + 6, a + 6});
    }
  return s;
}

}  // namespace tessella::fixtures
