#pragma once
// Dome tissues: the usual starting shape of shoot apical meristem models.

#include "tessella/tissue/voronoi.hpp"

namespace tessella {

/// A curved-surface tissue for shoot apical meristem models: a 2D Voronoi
/// tissue of the dome's footprint disk, lifted onto the dome surface (every
/// vertex lies on the surface, Embedding::Surface). Only vertices are lifted:
/// walls are straight chords and cells slightly non-planar polygons.
struct Dome {
  enum class Shape { SphericalCap, Paraboloid };
  Shape shape = Shape::SphericalCap;
  double base_radius = 1.0;  ///< radius of the footprint disk
  double height = 0.5;       ///< height of the summit above the base plane
  Vec3 base_center = Vec3::Zero();
  /// Height of the surface above the base plane at footprint radius r in
  /// [0, base_radius]: the sphere through the base circle and the summit
  /// (needs height <= base_radius), or height * (1 - r^2 / base_radius^2).
  /// InputError for r outside the footprint or invalid dome fields.
  double heightAt(double r) const;
  /// Projects a point vertically onto the surface.
  Vec3 lift(const Vec3& p) const;
};
/// footprint_seeds: positions in the footprint disk (their z is ignored);
/// the footprint is a 256-segment polygon as for Disk.
Tissue domeTissue(std::span<const Vec3> footprint_seeds, const Dome& dome,
                  const VoronoiOptions& options = {});

}  // namespace tessella
