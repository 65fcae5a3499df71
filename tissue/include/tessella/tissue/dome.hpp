#pragma once
// Dome tissues: the usual starting shape of shoot apical meristem models.

#include "tessella/tissue/voronoi.hpp"

namespace tessella {

/// A curved-surface tissue for shoot apical meristem models: a 2D Voronoi
/// tissue of the dome's footprint disk, lifted onto the dome surface (every
/// vertex lies on the surface, Embedding::Surface).
struct Dome {
  enum class Shape { SphericalCap, Paraboloid };
  Shape shape = Shape::SphericalCap;
  double base_radius = 1.0;  ///< radius of the footprint disk
  double height = 0.5;       ///< height of the summit above the base plane
  Vec3 base_center = Vec3::Zero();
  /// Height of the surface above the base plane at footprint radius r.
  double heightAt(double r) const;
  /// Projects a point vertically onto the surface.
  Vec3 lift(const Vec3& p) const;
};
Tissue domeTissue(std::span<const Vec3> footprint_seeds, const Dome& dome,
                  const VoronoiOptions& options = {});

}  // namespace tessella
