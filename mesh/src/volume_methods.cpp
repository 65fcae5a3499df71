// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// What the two volume methods share: the seed point of a cell's region.

#include "volume_methods.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "interior_point.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::mesh::detail {

Vec3 cellSeed(const Tissue& t, const WallTriangulation& walls, CellId c) {
  std::vector<Triangle> outward;
  for (OrientedFace of : t.topology().volumeFaces(handle_cast<VolumeId>(c)))
    for (const auto& tri : walls.wall_triangles[of.handle().index()]) {
      const Vec3 &a = walls.points[static_cast<std::size_t>(tri[0])], &b = walls.points[static_cast<std::size_t>(tri[1])],
                 &d = walls.points[static_cast<std::size_t>(tri[2])];
      outward.push_back(of.reversed() ? Triangle{a, d, b} : Triangle{a, b, d});
    }
  const double size = std::cbrt(cellMeasure(t, c));
  const auto seed = interiorPoint(outward, cellCentroid(t, c), 1e-6 * size);
  if (!seed)
    throw GeometryError("volume mesher: found no point strictly inside cell " + std::to_string(c.index()) +
                            " to seed its region (the cell is too thin or not closed)",
                        ElementId{3, c.index()});
  return *seed;
}

}  // namespace tessella::mesh::detail
