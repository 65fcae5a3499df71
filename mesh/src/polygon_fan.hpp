// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: the fan surface of a polygon loop, as tissue/geometry.hpp measures
// it where it does not fold (triangles from the mean of the loop vertices,
// signed against the mean normal; where it folds, the meshers take the
// triangles of tessella::polygonTriangulation()). The meshers reproduce the
// measured surface so that mesh measures equal the tissue's.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "tessella/tissue/tissue.hpp"
#include <Eigen/Geometry>

#include "tessella/tissue/vec3.hpp"

namespace tessella::mesh::detail {

inline std::vector<Vec3> loopPositions(const Tissue& t, FaceId f) {
  std::vector<Vec3> out;
  for (VertexId v : t.topology().faceVertices(f)) out.push_back(t.position(v));
  return out;
}

inline Vec3 loopMean(std::span<const Vec3> loop) {
  Vec3 m = Vec3::Zero();
  for (const Vec3& p : loop) m += p;
  return m / static_cast<double>(loop.size());
}

/// Vector area of the fan (half the sum of the fan triangles' cross products).
inline Vec3 fanVectorArea(std::span<const Vec3> loop, const Vec3& center) {
  Vec3 a = Vec3::Zero();
  for (std::size_t i = 0; i < loop.size(); ++i)
    a += (loop[i] - center).cross(loop[(i + 1) % loop.size()] - center);
  return 0.5 * a;
}

/// Area of fan triangle (center, a, b), signed against the unit normal n.
inline double fanTriangleSignedArea(const Vec3& center, const Vec3& a, const Vec3& b, const Vec3& n) {
  const Vec3 c = (a - center).cross(b - center);
  const double area = 0.5 * c.norm();
  return c.dot(n) >= 0.0 ? area : -area;
}

struct FanSurface {
  Vec3 center = Vec3::Zero();
  Vec3 normal = Vec3::Zero();        ///< unit mean normal (zero if degenerate)
  double area = 0.0;                 ///< sum of signed fan triangle areas
  double min_triangle_area = 0.0;    ///< smallest signed fan triangle area
  int min_triangle = -1;             ///< loop position of that triangle
  double planarity_deviation = 0.0;  ///< max distance of a vertex from the mean plane
};

inline FanSurface fanSurface(std::span<const Vec3> loop) {
  FanSurface s;
  s.center = loopMean(loop);
  const Vec3 va = fanVectorArea(loop, s.center);
  const double norm = va.norm();
  if (norm > 0.0) s.normal = va / norm;
  s.min_triangle_area = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const double a = fanTriangleSignedArea(s.center, loop[i], loop[(i + 1) % loop.size()], s.normal);
    s.area += a;
    if (a < s.min_triangle_area) {
      s.min_triangle_area = a;
      s.min_triangle = static_cast<int>(i);
    }
    s.planarity_deviation = std::max(s.planarity_deviation, std::abs((loop[i] - s.center).dot(s.normal)));
  }
  return s;
}

/// Smallest angle of a triangle, in degrees.
inline double smallestAngleDegrees(const std::array<Vec3, 3>& c) {
  double smallest = 180.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3 a = c[(k + 1) % 3] - c[k], b = c[(k + 2) % 3] - c[k];
    smallest = std::min(smallest, std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / std::numbers::pi);
  }
  return smallest;
}

/// Smallest interior angle of a planar polygon whose loop runs counter-clockwise
/// about the unit normal n, in degrees (reflex corners count as more than 180).
inline double smallestCornerDegrees(std::span<const Vec3> loop, const Vec3& n) {
  double smallest = 360.0;
  const std::size_t m = loop.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 back = loop[(i + m - 1) % m] - loop[i], ahead = loop[(i + 1) % m] - loop[i];
    double angle = std::atan2(n.dot(ahead.cross(back)), ahead.dot(back)) * 180.0 / std::numbers::pi;
    if (angle < 0.0) angle += 360.0;
    smallest = std::min(smallest, angle);
  }
  return smallest;
}

}  // namespace tessella::mesh::detail
