// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The clipping domains of the Voronoi generators as convex polygons/polyhedra.

#include "voronoi_domain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <map>
#include <numbers>
#include <utility>

#include <Eigen/Geometry>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::detail {
namespace {

void requireFinite(const Vec3& p, const char* what) {
  if (!p.allFinite()) throw InputError(std::string(what) + " must be finite, got " + formatPoint(p));
}

void requirePositiveRadius(double r, const char* what) {
  if (!std::isfinite(r) || !(r > 0))
    throw InputError(std::string(what) + ".radius must be a positive finite number, got " +
                     formatNumber(r));
}

ConvexDomain2 polygonDomain(std::vector<Vec2> corners) {
  ConvexDomain2 d;
  d.corners = std::move(corners);
  const std::size_t n = d.corners.size();
  d.lo = d.hi = d.corners[0];
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& a = d.corners[k];
    const Vec2& b = d.corners[(k + 1) % n];
    const Vec2 edge = b - a;
    const Vec2 outward = Vec2(edge.y(), -edge.x()).normalized();  // CCW polygon: right of the edge
    d.sides.push_back({outward, outward.dot(a)});
    d.lo = d.lo.cwiseMin(a);
    d.hi = d.hi.cwiseMax(a);
  }
  d.scale = (d.hi - d.lo).norm();
  return d;
}

ConvexDomain3 boxDomain(const Vec3& lo, const Vec3& hi) {
  ConvexDomain3 d;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 n = Vec3::Zero();
    n[axis] = -1;
    d.faces.push_back({n, -lo[axis]});
    n[axis] = 1;
    d.faces.push_back({n, hi[axis]});
  }
  d.lo = lo;
  d.hi = hi;
  d.scale = (hi - lo).norm();
  d.is_box = true;
  d.center = (lo + hi) / 2;
  d.volume_value = (hi - lo).prod();
  return d;
}

}  // namespace

double ConvexDomain2::excess(const Vec2& p) const {
  double worst = -std::numeric_limits<double>::infinity();
  for (const HalfPlane& s : sides) worst = std::max(worst, s.excess(p));
  return worst;
}

double ConvexDomain2::area() const {
  double twice = 0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Vec2& a = corners[k];
    const Vec2& b = corners[(k + 1) % corners.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return twice / 2;
}

double ConvexDomain3::excess(const Vec3& p) const {
  auto scan = [&](std::size_t begin, std::size_t end, double worst) {
    for (std::size_t k = begin; k < end; ++k) worst = std::max(worst, faces[k].excess(p));
    return worst;
  };
  const double none = -std::numeric_limits<double>::infinity();
  if (groups.empty() || !p.allFinite()) return scan(0, faces.size(), none);
  // A face of group g has excess n . q - depth <= |q| cos(max(0, angle(q, axis) - half)) - min_depth
  // (q = p - center). Groups whose bound, plus a slack far above the rounding
  // of the bounds, lies below the largest excess found cannot hold it: the
  // result is the maximum over every face, as a full scan gives.
  const Vec3 q = p - center;
  const double r = q.norm();
  const double slack = 1e-8 * (scale + r + center.norm());
  std::array<double, kMaxFaceGroups> bound{};
  std::size_t first = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const FaceGroup& fg = groups[g];
    const double c = r > 0 ? std::clamp(fg.axis.dot(q) / r, -1.0, 1.0) : 1.0;
    const double cb = c >= fg.cos_half ? 1.0 : c * fg.cos_half + std::sqrt(std::max(0.0, 1 - c * c)) * fg.sin_half;
    bound[g] = r * cb - fg.min_depth;
    if (bound[g] > bound[first]) first = g;
  }
  double worst = scan(groups[first].begin, groups[first].end, none);
  for (std::size_t g = 0; g < groups.size(); ++g)
    if (g != first && bound[g] + slack >= worst) worst = scan(groups[g].begin, groups[g].end, worst);
  return worst;
}

void groupFaces(ConvexDomain3& d, std::size_t count) {
  const std::size_t n = d.faces.size();
  if (count == 0 || count > ConvexDomain3::kMaxFaceGroups || n % count != 0)
    throw GeometryError("groupFaces: " + std::to_string(n) + " faces do not split into " + std::to_string(count) +
                        " groups");
  d.groups.clear();
  for (std::size_t g = 0; g < count; ++g) {
    FaceGroup fg;
    fg.begin = g * (n / count);
    fg.end = fg.begin + n / count;
    Vec3 sum = Vec3::Zero();
    for (std::size_t k = fg.begin; k < fg.end; ++k) sum += d.faces[k].normal;
    if (!(sum.norm() > 0)) {  // normals cancelling out: no useful cone, scan every face
      d.groups.clear();
      return;
    }
    fg.axis = sum.normalized();
    fg.cos_half = 1.0;
    fg.min_depth = std::numeric_limits<double>::infinity();
    for (std::size_t k = fg.begin; k < fg.end; ++k) {
      fg.cos_half = std::min(fg.cos_half, d.faces[k].normal.dot(fg.axis));
      fg.min_depth = std::min(fg.min_depth, d.faces[k].offset - d.faces[k].normal.dot(d.center));
    }
    fg.cos_half = std::max(-1.0, fg.cos_half - 1e-12);  // rounded outwards: a wider cone
    fg.sin_half = std::min(1.0, std::sqrt(std::max(0.0, 1 - fg.cos_half * fg.cos_half)) + 1e-12);
    d.groups.push_back(fg);
  }
}

ConvexDomain2 makeDomain(const Rectangle& r) {
  requireFinite(r.min, "rectangle.min");
  requireFinite(r.max, "rectangle.max");
  if (!(r.max.x() > r.min.x()) || !(r.max.y() > r.min.y()))
    throw InputError("rectangle.max " + formatPoint(r.max) + " must exceed rectangle.min " + formatPoint(r.min) +
                     " in x and y");
  ConvexDomain2 d = polygonDomain({{r.min.x(), r.min.y()},
                                   {r.max.x(), r.min.y()},
                                   {r.max.x(), r.max.y()},
                                   {r.min.x(), r.max.y()}});
  d.is_rectangle = true;
  d.center = (d.lo + d.hi) / 2;
  return d;
}

ConvexDomain2 makeDomain(const Disk& disk) {
  requireFinite(disk.center, "disk.center");
  requirePositiveRadius(disk.radius, "disk");
  if (disk.boundary_segments < 8 || disk.boundary_segments > (1 << 20))
    throw InputError("disk.boundary_segments must be in [8, 1048576], got " +
                     std::to_string(disk.boundary_segments));
  const int n = disk.boundary_segments;
  std::vector<Vec2> corners;
  corners.reserve(n);
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * std::numbers::pi * k / n;
    corners.emplace_back(disk.center.x() + disk.radius * std::cos(angle),
                         disk.center.y() + disk.radius * std::sin(angle));
  }
  ConvexDomain2 d = polygonDomain(std::move(corners));
  d.center = Vec2(disk.center.x(), disk.center.y());
  // The polygon's inradius, less a rounding margin.
  d.inner_radius = disk.radius * std::cos(std::numbers::pi / n) * (1 - 1e-12);
  return d;
}

ConvexDomain3 makeDomain(const Box& b) {
  requireFinite(b.min, "box.min");
  requireFinite(b.max, "box.max");
  if (!(b.max.array() > b.min.array()).all())
    throw InputError("box.max " + formatPoint(b.max) + " must exceed box.min " + formatPoint(b.min) +
                     " in x, y and z");
  return boxDomain(b.min, b.max);
}

Icosphere makeIcosphere(const Ball& b) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  Icosphere s;
  s.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& v : s.vertices) v.normalize();
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < b.subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int c) {
      const auto key = std::minmax(a, c);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      s.vertices.push_back((s.vertices[a] + s.vertices[c]).normalized());
      const int id = static_cast<int>(s.vertices.size()) - 1;
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> finer;
    finer.reserve(s.triangles.size() * 4);
    for (const auto& tri : s.triangles) {
      const int ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
      finer.push_back({tri[0], ab, ca});
      finer.push_back({tri[1], bc, ab});
      finer.push_back({tri[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    s.triangles = std::move(finer);
  }
  for (Vec3& v : s.vertices) v = b.center + b.radius * v;
  return s;
}

ConvexDomain3 makeDomain(const Ball& b) {
  requireFinite(b.center, "ball.center");
  requirePositiveRadius(b.radius, "ball");
  if (b.subdivisions < 0 || b.subdivisions > 6)
    throw InputError("ball.subdivisions must be in [0, 6], got " + std::to_string(b.subdivisions));
  const Icosphere sphere = makeIcosphere(b);
  ConvexDomain3 d;
  d.center = b.center;
  d.lo = b.center - Vec3::Constant(b.radius);
  d.hi = b.center + Vec3::Constant(b.radius);
  d.scale = (d.hi - d.lo).norm();
  double inradius = b.radius;
  for (const auto& tri : sphere.triangles) {
    const Vec3& p0 = sphere.vertices[tri[0]];
    const Vec3& p1 = sphere.vertices[tri[1]];
    const Vec3& p2 = sphere.vertices[tri[2]];
    const Vec3 n = (p1 - p0).cross(p2 - p0).normalized();
    d.faces.push_back({n, n.dot(p0)});
    inradius = std::min(inradius, n.dot(p0) - n.dot(b.center));
    // Volume of the cone from the centre over this triangle.
    d.volume_value += (p0 - b.center).dot((p1 - b.center).cross(p2 - b.center)) / 6;
  }
  d.inner_radius = inradius * (1 - 1e-12);
  // The subdivision keeps each icosahedron face's triangles together: one
  // group per face, so excess() reads about a twentieth of the faces.
  if (b.subdivisions >= 2) groupFaces(d, 20);
  return d;
}

}  // namespace tessella::detail
