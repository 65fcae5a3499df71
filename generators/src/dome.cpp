// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Dome tissues: a planar Voronoi tissue of the footprint disk whose vertices
// are lifted vertically onto a spherical cap or a paraboloid. Only vertices
// move: walls stay straight chords between lifted vertices and cells are
// (slightly non-planar) polygons, as everywhere in a Surface tissue.

#include "tessella/generators/dome.hpp"

#include <algorithm>
#include <utility>
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
  // The rim onto the base circle: the clipping domain is a polygon (256 sides) inscribed in the footprint circle,
  // so the rim vertices between its corners lie up to R (1 - cos(pi/256)) = 7.5e-5 R inside the circle, and
  // lifted they would sit above the base plane (up to 1e-4 R; docs/mechanics.md, "Cost"). Every vertex of an edge
  // that only one cell uses is pushed radially onto the circle, where the lift puts it in the base plane.
  std::vector<std::pair<Index, Index>> edges;
  edges.reserve(cells.loops.size());
  for (std::size_t q = 0; q + 1 < cells.offsets.size(); ++q)
    for (Index k = cells.offsets[q]; k < cells.offsets[q + 1]; ++k) {
      const Index a = cells.loops[k], b = cells.loops[k + 1 == cells.offsets[q + 1] ? cells.offsets[q] : k + 1];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1)
      for (const Index v : {edges[i].first, edges[i].second}) {
        Vec3& p = cells.positions[v];
        const Vec3 d(p.x() - footprint.center.x(), p.y() - footprint.center.y(), 0.0);
        if (d.norm() > 0.0) p = footprint.center + d * (footprint.radius / d.norm());
      }
    i = j;
  }
  for (Vec3& p : cells.positions) p = dome.lift(p);
  return buildPolygonTissue(std::move(cells.positions), cells.offsets, cells.loops, Embedding::Surface,
                            cells.order);
}

}  // namespace tessella
