// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private: clipped Voronoi cells as plain arrays, before they become a Tissue
// (shared by the generators, the dome and Lloyd relaxation).

#include <cstdint>
#include <span>
#include <vector>

#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/vec3.hpp"
#include "voronoi_domain.hpp"

namespace tessella::detail {

struct ClippedCells2 {
  std::vector<Vec3> positions;  // vertices (z = 0), numbered by first use in `loops`
  std::vector<Index> offsets;   // loop q is loops[offsets[q] .. offsets[q+1]),
  std::vector<Index> loops;     //   counter-clockwise, the loop of cell order[q]
  std::vector<Index> order;     //   (cell k = seed k; cells listed along a Hilbert curve)
  std::vector<Vec3> centroids;  // of each clipped cell, by cell (CentroidsOnly)
};

struct ClippedCells3 {
  std::vector<Vec3> positions;      // vertices, numbered by first use
  std::vector<Index> face_offsets;  // walls, each listed once: face k is
  std::vector<Index> face_loops;    //   face_loops[face_offsets[k] .. face_offsets[k+1])
  std::vector<Index> cell_offsets;  // cell k = seed k: its walls are
  std::vector<CellFace> cell_faces; //   cell_faces[cell_offsets[k] .. cell_offsets[k+1])
  std::vector<Vec3> centroids;      // of each clipped cell
  // Per cell: read off the triangulation with all its Voronoi vertices
  // distinct, so closed by construction (CellComplex::addVolumes).
  std::vector<std::uint8_t> closed;
};

/// What to compute: Lloyd relaxation needs the centroids only.
enum class CellOutput { CentroidsOnly, Complex };

/// Voronoi cells of checked seeds (checkSeeds2/3 passed) clipped to the
/// domain. Throws InputError for duplicate or collinear/coplanar seeds.
ClippedCells2 clipVoronoi2(std::span<const Vec3> seeds, const ConvexDomain2& domain,
                           double duplicate_tolerance, CellOutput output);
ClippedCells3 clipVoronoi3(std::span<const Vec3> seeds, const ConvexDomain3& domain,
                           double duplicate_tolerance, CellOutput output);

// Whether the 3D triangulation of these seeds can be built as two halves side
// by side (voronoi_3d.cpp; with 2 threads or more and 5000 seeds or more
// clipVoronoi3 does so, else it builds one triangulation of all seeds).
bool triangulatesInHalves3(std::span<const Vec3> seeds);

/// Lloyd relaxation: `iterations` times, every seed moves to the centroid of
/// its clipped cell.
std::vector<Vec3> lloydRelax(std::span<const Vec3> seeds, const ConvexDomain2& domain,
                             int iterations, double duplicate_tolerance);
std::vector<Vec3> lloydRelax(std::span<const Vec3> seeds, const ConvexDomain3& domain,
                             int iterations, double duplicate_tolerance);

}  // namespace tessella::detail
