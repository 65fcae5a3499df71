// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: CGAL Delaunay refinement with a vertex budget, so a refinement
// that does not settle (an angle bound above the proven 20.7 degrees, a
// geometry CGAL cannot satisfy) raises a GeometryError instead of hanging.
//
// The budget is a generous multiple of what a graded mesh of the input needs:
// every boundary point can force a graded fan of O(log(L / d_min)) points
// (L the extent, d_min the closest pair of input points) and the size bound
// needs about area / (area of an equilateral triangle of side h) points.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>

namespace tessella::mesh::detail {

/// Vertex budget for refining a region of `area` with `boundary_points`
/// input points, extent `extent`, closest input points `min_spacing` apart,
/// size bound `max_edge` (0 = none).
inline std::size_t refinementBudget(std::size_t boundary_points, double area, double extent, double min_spacing,
                                    double max_edge) {
  const double grading = 1.0 + std::log2(1.0 + extent / std::max(min_spacing, 1e-300));
  double points = static_cast<double>(boundary_points) * grading;
  if (max_edge > 0.0) points += area / (0.4330127018922193 * max_edge * max_edge);
  return static_cast<std::size_t>(std::min(1e9, 10000.0 + 100.0 * points));
}

/// Runs `mesher` (a CGAL Delaunay_mesher_2 or Delaunay_mesher_no_edge_refinement_2
/// on `cdt`) one insertion at a time; calls `exceeded(vertices)` (which must
/// throw) when the triangulation grows past `budget` vertices.
/// `domain_specified`: the faces' in_domain marks are already set.
template <typename Mesher, typename Cdt>
void refineWithinBudget(Mesher& mesher, const Cdt& cdt, std::size_t budget,
                        const std::function<void(std::size_t)>& exceeded, bool domain_specified = false) {
  mesher.init(domain_specified);
  while (!mesher.is_refinement_done()) {
    if (cdt.number_of_vertices() > budget) exceeded(cdt.number_of_vertices());
    mesher.step_by_step_refine_mesh();
  }
}

}  // namespace tessella::mesh::detail
