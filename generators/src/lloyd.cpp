// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Lloyd relaxation: seeds move to the centroids of their clipped Voronoi
// cells, which evens out cell sizes (a centroidal Voronoi tessellation in the
// limit). A centroid lies inside its convex cell, hence inside the domain, and
// distinct cells have distinct centroids, so relaxed seeds stay valid input.

#include "voronoi_cells.hpp"

namespace tessella::detail {
namespace {

template <typename Domain, typename Clip>
std::vector<Vec3> relax(std::span<const Vec3> seeds, const Domain& domain, int iterations,
                        double duplicate_tolerance, Clip clip) {
  std::vector<Vec3> current(seeds.begin(), seeds.end());
  for (int it = 0; it < iterations; ++it)
    current = clip(current, domain, duplicate_tolerance, CellOutput::CentroidsOnly).centroids;
  return current;
}

}  // namespace

std::vector<Vec3> lloydRelax(std::span<const Vec3> seeds, const ConvexDomain2& domain,
                             int iterations, double duplicate_tolerance) {
  return relax(seeds, domain, iterations, duplicate_tolerance, clipVoronoi2);
}

std::vector<Vec3> lloydRelax(std::span<const Vec3> seeds, const ConvexDomain3& domain,
                             int iterations, double duplicate_tolerance) {
  return relax(seeds, domain, iterations, duplicate_tolerance, clipVoronoi3);
}

}  // namespace tessella::detail
