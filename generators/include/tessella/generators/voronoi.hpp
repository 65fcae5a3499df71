// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Voronoi tissues: cells are the Voronoi regions of seed points (computed as
// the dual of CGAL's Delaunay triangulation), clipped to a domain. Cell
// neighbourhood comes from the triangulation; walls are its dual.
// Cell k of the result is the cell of seed k. See docs/generators.md for the
// construction, its tolerances and its measured speed.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tessella/tissue/tissue.hpp"

namespace tessella {

/// 2D domains: an axis-aligned rectangle or a disk (in the z = 0 plane).
struct Rectangle {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3(1, 1, 0);
};
struct Disk {
  Vec3 center = Vec3::Zero();
  double radius = 1.0;
  /// The disk boundary is a polygon with this many segments per full turn
  /// (measures are compared against that polygon's area, not pi r^2).
  int boundary_segments = 256;
};
/// 3D domains: an axis-aligned box or a ball.
struct Box {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Ones();
};
struct Ball {
  Vec3 center = Vec3::Zero();
  double radius = 1.0;
  /// The ball boundary is a convex polyhedron (an icosphere of this
  /// subdivision level); measures refer to that polyhedron.
  int subdivisions = 3;
};

struct VoronoiOptions {
  /// Lloyd relaxation iterations (seeds moved to their cell centroids).
  int lloyd_iterations = 0;
  /// Seeds closer than this (relative to the domain's bounding-box diagonal)
  /// are duplicates: an InputError names both seed indices. Must lie in
  /// [1e-9, 0.1]: vertices closer than 1e-10 of the domain size are welded.
  double duplicate_tolerance = 1e-9;
};

/// Uniform random seeds in a domain, reproducible from rng_seed: a
/// std::mt19937_64(rng_seed) with u = (engine() >> 11) * 2^-53, so the same
/// rng_seed gives the same seeds with any standard library. Disks and balls
/// are sampled by rejection inside their boundary polygon / polyhedron.
std::vector<Vec3> randomSeeds(const Rectangle& domain, std::size_t count, std::uint64_t rng_seed);
std::vector<Vec3> randomSeeds(const Disk& domain, std::size_t count, std::uint64_t rng_seed);
std::vector<Vec3> randomSeeds(const Box& domain, std::size_t count, std::uint64_t rng_seed);
std::vector<Vec3> randomSeeds(const Ball& domain, std::size_t count, std::uint64_t rng_seed);

/// Reads seeds from a CSV file of "x,y" (dim 2, z = 0) or "x,y,z" (dim 3)
/// rows; an optional header row of names, blank lines and '#' comment lines
/// are skipped. The first row is a header only when every field is a name
/// (starts with a letter or '_', not a number); a first row mixing names and
/// numbers is an error. InputError names the file, line, column and value.
std::vector<Vec3> readSeedsCsv(const std::string& path, int dim);

/// Voronoi tissues clipped to the domain. Seeds outside the domain (for a
/// disk / ball: outside its boundary polygon / polyhedron), 2D seeds with
/// z != 0, non-finite coordinates, duplicate seeds, fewer than 3 (2D) / 4 (3D)
/// seeds, or all seeds collinear / coplanar raise InputError naming the seed
/// index and coordinates. Seeds on the boundary are fine. 2D loops run
/// counter-clockwise seen from +z. Zero-length edges of cocircular seeds (a
/// square grid) are merged. In 3D, seeds cospherical to within ~1e-9 but not
/// exactly may raise GeometryError naming two seeds (never a broken tissue).
Tissue voronoiTissue(std::span<const Vec3> seeds, const Rectangle& domain,
                     const VoronoiOptions& options = {});
Tissue voronoiTissue(std::span<const Vec3> seeds, const Disk& domain,
                     const VoronoiOptions& options = {});
Tissue voronoiTissue(std::span<const Vec3> seeds, const Box& domain,
                     const VoronoiOptions& options = {});
Tissue voronoiTissue(std::span<const Vec3> seeds, const Ball& domain,
                     const VoronoiOptions& options = {});

}  // namespace tessella
