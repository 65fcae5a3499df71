// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Dome tissues: a planar Voronoi tissue of the footprint disk whose vertices
// are lifted vertically onto a spherical cap or a paraboloid. Only vertices
// move: walls stay straight chords between lifted vertices and cells are
// (slightly non-planar) polygons, as everywhere in a Surface tissue.

#include "tessella/generators/dome.hpp"

#include <vector>

#include "tessella/tissue/builders.hpp"
#include "voronoi_cells.hpp"
#include "voronoi_seed_checks.hpp"

namespace tessella {

Tissue domeTissue(std::span<const Vec3> footprint_seeds, const Dome& dome, const VoronoiOptions& options) {
  checkDome(dome);
  detail::checkOptions(options);
  Disk footprint;
  footprint.center = Vec3(dome.base_center.x(), dome.base_center.y(), 0);
  footprint.radius = dome.base_radius;
  const detail::ConvexDomain2 domain = detail::makeDomain(footprint);
  // Footprint seeds are positions in the base plane: their z is not used.
  std::vector<Vec3> seeds(footprint_seeds.begin(), footprint_seeds.end());
  for (Vec3& s : seeds) s.z() = 0;
  detail::checkSeeds2(seeds, domain);
  if (options.lloyd_iterations > 0)
    seeds = detail::lloydRelax(seeds, domain, options.lloyd_iterations, options.duplicate_tolerance);
  detail::ClippedCells2 cells =
      detail::clipVoronoi2(seeds, domain, options.duplicate_tolerance, detail::CellOutput::Complex);
  for (Vec3& p : cells.positions) p = dome.lift(p);
  return buildPolygonTissue(std::move(cells.positions), cells.offsets, cells.loops, Embedding::Surface,
                            cells.order);
}

}  // namespace tessella
