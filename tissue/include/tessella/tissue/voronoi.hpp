#pragma once
// Voronoi tissues: cells are the Voronoi regions of seed points (computed as
// the dual of CGAL's Delaunay triangulation), clipped to a domain. Cell
// neighbourhood comes from the triangulation; walls are its dual.

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
  /// Seeds closer than this (relative to the domain size) are duplicates:
  /// an InputError names both seed indices.
  double duplicate_tolerance = 1e-9;
};

/// Uniform random seeds in a domain, reproducible from rng_seed.
std::vector<Vec3> randomSeeds(const Rectangle& domain, std::size_t count, std::uint64_t rng_seed);
std::vector<Vec3> randomSeeds(const Disk& domain, std::size_t count, std::uint64_t rng_seed);
std::vector<Vec3> randomSeeds(const Box& domain, std::size_t count, std::uint64_t rng_seed);
std::vector<Vec3> randomSeeds(const Ball& domain, std::size_t count, std::uint64_t rng_seed);

/// Reads seeds from a CSV file of "x,y" or "x,y,z" rows (an optional header
/// row of names is skipped); InputError names the file, line and value.
std::vector<Vec3> readSeedsCsv(const std::string& path, int dim);

/// Voronoi tissues clipped to the domain. Seeds outside the domain, duplicate
/// seeds, fewer than 3 (2D) / 4 (3D) seeds, or all seeds collinear / coplanar
/// raise InputError naming the seed index and coordinates.
Tissue voronoiTissue(std::span<const Vec3> seeds, const Rectangle& domain,
                     const VoronoiOptions& options = {});
Tissue voronoiTissue(std::span<const Vec3> seeds, const Disk& domain,
                     const VoronoiOptions& options = {});
Tissue voronoiTissue(std::span<const Vec3> seeds, const Box& domain,
                     const VoronoiOptions& options = {});
Tissue voronoiTissue(std::span<const Vec3> seeds, const Ball& domain,
                     const VoronoiOptions& options = {});

}  // namespace tessella
