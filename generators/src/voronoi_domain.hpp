// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private: the clipping domains of the Voronoi generators as convex polygons
// (2D) and convex polyhedra (3D), given by their sides / faces as half-spaces
// n.x <= h with unit n. A disk is its inscribed regular polygon and a ball its
// inscribed icosphere: those polygons are the documented domains whose area /
// volume the cells add up to.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "tessella/generators/voronoi.hpp"

namespace tessella::detail {

using Vec2 = Eigen::Vector2d;

struct HalfPlane {
  Vec2 normal;  // unit, pointing out of the domain
  double offset = 0.0;
  double excess(const Vec2& p) const { return normal.dot(p) - offset; }
};

struct HalfSpace {
  Vec3 normal;  // unit, pointing out of the domain
  double offset = 0.0;
  double excess(const Vec3& p) const { return normal.dot(p) - offset; }
};

/// A convex polygon, corners counter-clockwise; side k runs from corner k to k+1.
struct ConvexDomain2 {
  std::vector<Vec2> corners;
  std::vector<HalfPlane> sides;
  Vec2 lo, hi;               // bounding box
  double scale = 1.0;        // bounding-box diagonal: the length unit of tolerances
  double inner_radius = 0.0; // a disk around `center` inside the polygon (0: none)
  Vec2 center = Vec2::Zero();
  bool is_rectangle = false;
  /// How far p lies outside (positive) or inside (negative) the polygon.
  double excess(const Vec2& p) const;
  double area() const;
};

/// Consecutive faces of a ConvexDomain3 whose outward normals lie in a cone
/// around `axis`: excess() skips the groups that cannot hold the maximum.
struct FaceGroup {
  Vec3 axis = Vec3::UnitZ();               // unit
  double cos_half = -1.0, sin_half = 0.0;  // the cone's half-angle, rounded outwards
  double min_depth = 0.0;                  // least offset - normal . center over the group
  std::size_t begin = 0, end = 0;          // faces[begin .. end)
};

/// A convex polyhedron given by its face planes.
struct ConvexDomain3 {
  std::vector<HalfSpace> faces;
  Vec3 lo, hi;
  double scale = 1.0;
  double inner_radius = 0.0;
  Vec3 center = Vec3::Zero();
  bool is_box = false;
  double volume_value = 0.0;
  /// Balls: the faces in at most kMaxFaceGroups groups (empty: excess scans every face).
  std::vector<FaceGroup> groups;
  static constexpr std::size_t kMaxFaceGroups = 32;
  /// How far p lies outside (positive) or inside (negative): the largest
  /// face excess, the same value with or without groups.
  double excess(const Vec3& p) const;
  double volume() const { return volume_value; }
};

/// Splits the faces of d into `count` groups of consecutive faces (count
/// divides the number of faces and is at most kMaxFaceGroups), each with the
/// cone of its normals.
void groupFaces(ConvexDomain3& d, std::size_t count);

/// Throw InputError naming the bad field when a domain is empty or not finite.
ConvexDomain2 makeDomain(const Rectangle& r);
ConvexDomain2 makeDomain(const Disk& d);
ConvexDomain3 makeDomain(const Box& b);
ConvexDomain3 makeDomain(const Ball& b);

/// The icosphere of a Ball: unit-sphere vertices scaled and translated, and
/// counter-clockwise (outward) triangles.
struct Icosphere {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};
Icosphere makeIcosphere(const Ball& b);

/// Relative tolerances (multiplied by the domain scale). A point within
/// kOnTolerance of a clipping plane is taken as lying on it (no sliver is
/// cut); vertices within kWeldTolerance are one vertex (zero-length edges
/// of cocircular / cospherical seeds disappear); seeds may lie up to
/// kOnTolerance outside the domain.
inline constexpr double kOnTolerance = 1e-12;
inline constexpr double kWeldTolerance = 1e-10;
inline constexpr double kMinDuplicateTolerance = 1e-9;
/// A Voronoi cell is read off the Delaunay triangulation (not clipped) when
/// all its vertices lie this far inside the domain.
inline constexpr double kInteriorMargin = 1e-8;

}  // namespace tessella::detail
