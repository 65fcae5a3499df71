// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Measure kernels shared by the per-element queries and the batched
// recompute: one implementation, so a cached value is bit-identical to a
// direct query. Internal to the tissue module.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "tessella/tissue/geometry.hpp"

namespace tessella::detail {

/// A fan triangle whose signed area is at most this fraction of the fan's
/// area makes the fan "fold" (the mesher's old star-shape test, unchanged).
inline constexpr double kFoldTolerance = 1e-12;

/// Orientation of (a, b, c) in the plane: twice the signed area.
inline double orient2(const std::array<double, 2>& a, const std::array<double, 2>& b,
                      const std::array<double, 2>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// Sign of orient2 where the rounding cannot have decided it, else 0: the
/// forward error bound of Shewchuk's orientation filter (collinear points,
/// such as the split points along a straight wall, come out 0, not noise).
inline int orient2Sign(const std::array<double, 2>& a, const std::array<double, 2>& b,
                       const std::array<double, 2>& c) {
  const double l = (b[0] - a[0]) * (c[1] - a[1]), r = (b[1] - a[1]) * (c[0] - a[0]);
  const double det = l - r, bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
  return det > bound ? 1 : (det < -bound ? -1 : 0);
}

/// Shape quality of a 3D triangle (1 equilateral, 0 degenerate), a function of
/// the point set only: the corners are sorted first, so a loop and its reverse
/// or rotation rank their ears alike.
inline double triangleQuality(Vec3 a, Vec3 b, Vec3 c) {
  const auto less = [](const Vec3& x, const Vec3& y) {
    return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
  };
  if (less(b, a)) std::swap(a, b);
  if (less(c, b)) std::swap(b, c);
  if (less(b, a)) std::swap(a, b);
  const double l2 = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return l2 > 0 ? 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / l2 : 0.0;
}

/// Triangles (loop positions, counter-clockwise about `normal`) of a loop
/// projected onto the plane through `origin` normal to `normal`, by ear
/// clipping. Among the valid ears (a convex corner whose closed triangle holds
/// no other remaining vertex) the best-shaped triangle in 3D is cut first,
/// ties going to the lexicographically smallest tip position, so the result
/// does not depend on the loop's start vertex or direction. A simple polygon
/// always has an ear; for a non-simple one (which validate() reports) the most
/// convex corner is cut when no ear is left, so the result is still n - 2
/// triangles covering the loop.
template <typename At>
std::vector<std::array<int, 3>> earClipTriangles(std::size_t n, At at, const Vec3& origin, const Vec3& normal) {
  const Vec3 e1 = normal.unitOrthogonal();
  const Vec3 e2 = normal.cross(e1);  // (e1, e2, normal) right-handed
  std::vector<std::array<double, 2>> q(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = at(i) - origin;
    q[i] = {d.dot(e1), d.dot(e2)};
  }
  std::vector<int> next(n), prev(n);
  for (std::size_t i = 0; i < n; ++i) {
    next[i] = static_cast<int>((i + 1) % n);
    prev[i] = static_cast<int>((i + n - 1) % n);
  }
  std::vector<std::uint8_t> alive(n, 1), known(n, 0), ear(n, 0);
  std::vector<double> quality(n, 0.0);
  const auto isEar = [&](int v) {
    const int a = prev[v], b = next[v];
    if (orient2Sign(q[a], q[v], q[b]) <= 0) return false;
    for (int w = next[b]; w != a; w = next[w])
      if (orient2Sign(q[a], q[v], q[w]) >= 0 && orient2Sign(q[v], q[b], q[w]) >= 0 &&
          orient2Sign(q[b], q[a], q[w]) >= 0)
        return false;
    return true;
  };
  const auto lexLess = [&](int x, int y) {
    const Vec3 &px = at(x), &py = at(y);
    return std::lexicographical_compare(px.data(), px.data() + 3, py.data(), py.data() + 3);
  };
  std::vector<std::array<int, 3>> out;
  out.reserve(n - 2);
  int start = 0;
  for (std::size_t left = n; left > 3; --left) {
    int best = -1;
    for (int v = start, k = 0; k < static_cast<int>(left); v = next[v], ++k) {
      if (!known[v]) {
        ear[v] = isEar(v);
        quality[v] = ear[v] ? triangleQuality(at(prev[v]), at(v), at(next[v])) : 0.0;
        known[v] = 1;
      }
      if (ear[v] && (best < 0 || quality[v] > quality[best] || (quality[v] == quality[best] && lexLess(v, best))))
        best = v;
    }
    if (best < 0) {
      // No ear (a non-simple or numerically degenerate loop): the most convex corner.
      double most = -std::numeric_limits<double>::infinity();
      for (int v = start, k = 0; k < static_cast<int>(left); v = next[v], ++k) {
        const double o = orient2(q[prev[v]], q[v], q[next[v]]);
        if (o > most || (o == most && lexLess(v, best))) most = o, best = v;
      }
    }
    if (best < 0) best = start;  // no finite orientation at all
    const int a = prev[best], b = next[best];
    out.push_back({a, best, b});
    alive[best] = 0;
    next[a] = b;
    prev[b] = a;
    start = a;
    // The corners next to the cut change; a vertex that was no ear may have
    // been blocked by the one cut: look at every non-ear again.
    for (int v = b, k = 0; k + 1 < static_cast<int>(left); v = next[v], ++k)
      if (v == a || v == b || !ear[v]) known[v] = 0;
  }
  out.push_back({prev[start], start, next[start]});
  return out;
}

/// The area of the fan triangle (apex, apex + p, apex + q), signed against `normal`.
inline double signedFanTriangle(const Vec3& p, const Vec3& q, const Vec3& normal) {
  const Vec3 t = p.cross(q);
  const double tn = t.norm();
  return 0.5 * (t.dot(normal) < 0 ? -tn : tn);
}

/// Area, centroid and second moment of the triangles (loop positions) lifted
/// to the loop's 3D points, about `origin`; each triangle signed against `normal`.
template <typename At>
void trianglesKernel(const std::vector<std::array<int, 3>>& tris, At at, const Vec3& origin, const Vec3& normal,
                     bool moments, double& area, Vec3& centroid, Mat3* second_moment) {
  double a = 0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  for (const auto& tri : tris) {
    const Vec3 p = at(tri[0]) - origin, q = at(tri[1]) - origin, r = at(tri[2]) - origin;
    const double ti = signedFanTriangle(q - p, r - p, normal);
    const Vec3 s = p + q + r;
    a += ti;
    first += ti * s / 3.0;
    if (moments)
      second += (ti / 12.0) * (p * p.transpose() + q * q.transpose() + r * r.transpose() + s * s.transpose());
  }
  area = a;
  const Vec3 g = a != 0 ? Vec3(first / a) : Vec3::Zero();
  centroid = origin + g;
  if (moments && second_moment) *second_moment = second - a * g * g.transpose();
}

/// Centroid of the kernel of the loop projected onto the plane through
/// `origin` normal to `normal` (the points from which the whole projected
/// polygon is visible: the intersection of its edges' inner half-planes),
/// placed in that plane. False when the kernel is empty or thinner than
/// 1e-6 of the polygon's extent (no fan apex to trust).
template <typename At>
bool kernelApex(std::size_t n, At at, const Vec3& origin, const Vec3& normal, Vec3& apex) {
  const Vec3 e1 = normal.unitOrthogonal();
  const Vec3 e2 = normal.cross(e1);
  std::vector<std::array<double, 2>> q(n);
  double lo0 = 0, hi0 = 0, lo1 = 0, hi1 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = at(i) - origin;
    q[i] = {d.dot(e1), d.dot(e2)};
    lo0 = std::min(lo0, q[i][0]), hi0 = std::max(hi0, q[i][0]);
    lo1 = std::min(lo1, q[i][1]), hi1 = std::max(hi1, q[i][1]);
  }
  std::vector<std::array<double, 2>> k{{lo0, lo1}, {hi0, lo1}, {hi0, hi1}, {lo0, hi1}}, next;
  for (std::size_t i = 0; i < n && !k.empty(); ++i) {
    // Keep the part left of the edge a -> b (the loop runs counter-clockwise).
    const auto &a = q[i], &b = q[(i + 1) % n];
    const auto side = [&](const std::array<double, 2>& p) { return orient2(a, b, p); };
    next.clear();
    for (std::size_t j = 0; j < k.size(); ++j) {
      const auto &p = k[j], &r = k[(j + 1) % k.size()];
      const double sp = side(p), sr = side(r);
      if (sp >= 0) next.push_back(p);
      if ((sp > 0 && sr < 0) || (sp < 0 && sr > 0)) {
        const double w = sp / (sp - sr);
        next.push_back({p[0] + w * (r[0] - p[0]), p[1] + w * (r[1] - p[1])});
      }
    }
    k.swap(next);
  }
  if (k.size() < 3) return false;
  double a2 = 0, cx = 0, cy = 0;
  for (std::size_t j = 0; j < k.size(); ++j) {
    const auto &p = k[j], &r = k[(j + 1) % k.size()];
    const double cr = (p[0] - k[0][0]) * (r[1] - k[0][1]) - (r[0] - k[0][0]) * (p[1] - k[0][1]);
    a2 += cr;
    cx += (p[0] + r[0] - 2 * k[0][0]) * cr;
    cy += (p[1] + r[1] - 2 * k[0][1]) * cr;
  }
  const double extent = std::max(hi0 - lo0, hi1 - lo1);
  double perimeter = 0;
  for (std::size_t j = 0; j < k.size(); ++j)
    perimeter += std::hypot(k[(j + 1) % k.size()][0] - k[j][0], k[(j + 1) % k.size()][1] - k[j][1]);
  // Mean width 2 * area / perimeter against the polygon's extent.
  if (!(a2 > 2e-6 * extent * perimeter)) return false;
  const double x = k[0][0] + cx / (3 * a2), y = k[0][1] + cy / (3 * a2);
  apex = origin + x * e1 + y * e2;
  return true;
}

/// Signed fan from `apex` (each triangle against `normal`): area, first
/// moment about apex, second moment about apex and the smallest triangle.
/// Without Centroid only the area and the smallest triangle (whether the fan
/// folds: the same sums, without the moments' cost).
template <bool Centroid = true, typename At>
[[gnu::always_inline]] inline void fanKernel(std::size_t n, At at, const Vec3& apex, const Vec3& normal,
                                             bool moments, double& area, Vec3& centroid, Mat3* second_moment,
                                             double& min_ti) {
  double a = 0;
  min_ti = std::numeric_limits<double>::infinity();
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  Vec3 p = at(n - 1) - apex;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 q = at(i) - apex;
    const double ti = signedFanTriangle(p, q, normal);
    a += ti;
    min_ti = std::min(min_ti, ti);
    if constexpr (Centroid) first += ti * (p + q) / 3.0;
    if (Centroid && moments) {
      const Vec3 s = p + q;
      second += (ti / 12.0) * (p * p.transpose() + q * q.transpose() + s * s.transpose());
    }
    p = q;
  }
  area = a;
  if constexpr (!Centroid) return;
  const Vec3 g = a != 0 ? Vec3(first / a) : Vec3::Zero();
  centroid = apex + g;
  if (moments && second_moment) *second_moment = second - a * g * g.transpose();
}

/// Where the general (non-planar) paths start: the loop's vertex mean and its
/// vector area (twice the area times the unit normal) summed over the fan
/// from that mean.
struct MeanFan {
  Vec3 mean;
  Vec3 vector_area;
};

template <typename At>
[[gnu::always_inline]] inline MeanFan meanFan(std::size_t n, At at) {
  Vec3 c0 = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) c0 += at(i);
  c0 /= static_cast<double>(n);
  Vec3 vec_area = Vec3::Zero();
  Vec3 p = at(n - 1) - c0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 q = at(i) - c0;
    vec_area += p.cross(q);
    p = q;
  }
  return {c0, vec_area};
}

/// The surface a non-planar (or 3D-wall) loop is measured on. `folded` false:
/// the fan from the vertex mean `apex`, which does not fold (every fan
/// triangle has a signed area above kFoldTolerance times the fan's area, or
/// the loop has no vector area at all). Otherwise, with the loop projected
/// onto the plane through its vertex mean normal to its vector area: the fan
/// from `apex`, the centroid of the projected polygon's kernel, when it has
/// one (the polygon is star-shaped, though not from its vertex mean), else
/// `triangles`, its ear-clipped triangulation. The same arithmetic as
/// polygonKernel, so both take the same decision.
struct FoldedSurface {
  bool folded = false;
  Vec3 apex = Vec3::Zero();
  std::vector<std::array<int, 3>> triangles;
};

template <typename At>
FoldedSurface foldedSurface(std::size_t n, At at) {
  FoldedSurface out;
  const MeanFan fan = meanFan(n, at);
  const Vec3& c0 = fan.mean;
  const Vec3& vec_area = fan.vector_area;
  out.apex = c0;
  const double len = vec_area.norm();
  if (!(len > 0)) return out;
  const Vec3 normal = vec_area / len;
  double a, min_ti;
  Vec3 unused;
  fanKernel<false>(n, at, c0, normal, false, a, unused, nullptr, min_ti);
  if (min_ti > kFoldTolerance * a) return out;
  out.folded = true;
  Vec3 apex;
  if (kernelApex(n, at, c0, normal, apex)) {
    double ka, kmin;
    fanKernel<false>(n, at, apex, normal, false, ka, unused, nullptr, kmin);
    if (kmin > kFoldTolerance * ka) {
      out.apex = apex;
      return out;
    }
  }
  out.triangles = earClipTriangles(n, at, c0, normal);
  return out;
}

// The planar (z = 0) case of polygonKernel: the shoelace in one pass, about
// the first vertex (any origin gives the same exact result; a local one keeps
// it well conditioned). Always inlined: the batched 2D recompute calls it
// straight from its loop, which is bandwidth-bound only when nothing is called.
template <bool Moments, typename At>
[[gnu::always_inline]] inline void planarPolygonKernel(std::size_t n, At at, double& area, Vec3& centroid,
                                                       Vec3& normal, Mat3* second_moment) {
  const Vec3 o = at(0);
  double a2 = 0, cx = 0, cy = 0, ixx = 0, iyy = 0, ixy = 0;
  double px = at(n - 1).x() - o.x(), py = at(n - 1).y() - o.y();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& qv = at(i);
    const double qx = qv.x() - o.x(), qy = qv.y() - o.y();
    const double cr = px * qy - qx * py;
    a2 += cr;
    cx += (px + qx) * cr;
    cy += (py + qy) * cr;
    if constexpr (Moments) {
      ixx += (px * px + px * qx + qx * qx) * cr;
      iyy += (py * py + py * qy + qy * qy) * cr;
      ixy += (px * qy + 2 * px * py + 2 * qx * qy + qx * py) * cr;
    }
    px = qx;
    py = qy;
  }
  const double signed_area = 0.5 * a2;
  const double s = signed_area < 0 ? -1.0 : 1.0;
  area = s * signed_area;
  normal = Vec3(0, 0, signed_area == 0 ? 0.0 : s);
  const double gx = signed_area == 0 ? 0.0 : cx / (3 * a2), gy = signed_area == 0 ? 0.0 : cy / (3 * a2);
  centroid = Vec3(o.x() + gx, o.y() + gy, o.z());
  if constexpr (Moments) {
    if (second_moment) {
      Mat3 m = Mat3::Zero();
      m(0, 0) = s * ixx / 12 - area * gx * gx;
      m(1, 1) = s * iyy / 12 - area * gy * gy;
      m(0, 1) = m(1, 0) = s * ixy / 24 - area * gx * gy;
      *second_moment = m;
    }
  }
}

// Loop of n points read through `at(i)`. See geometry.hpp for the definition.
template <typename At>
inline void polygonKernel(std::size_t n, At at, bool planar, bool moments, double& area,
                          Vec3& centroid, Vec3& normal, Mat3* second_moment, FoldedSurface* surface = nullptr) {
  if (planar) {
    if (moments)
      planarPolygonKernel<true>(n, at, area, centroid, normal, second_moment);
    else
      planarPolygonKernel<false>(n, at, area, centroid, normal, second_moment);
    return;
  }
  // General (surface or 3D wall): signed fan from the vertex mean.
  const MeanFan fan = meanFan(n, at);
  const Vec3& c0 = fan.mean;
  const Vec3& vec_area = fan.vector_area;
  const double len = vec_area.norm();
  normal = len > 0 ? Vec3(vec_area / len) : Vec3::Zero();
  double min_ti = 0;
  fanKernel(n, at, c0, normal, moments, area, centroid, second_moment, min_ti);
  if (len > 0 && !(min_ti > kFoldTolerance * area)) {
    // The fan folds over: the fan from the kernel's centroid, or the loop's own triangles (see foldedSurface).
    FoldedSurface f = foldedSurface(n, at);
    double kmin;
    if (f.triangles.empty())
      fanKernel(n, at, f.apex, normal, moments, area, centroid, second_moment, kmin);
    else
      trianglesKernel(f.triangles, at, c0, normal, moments, area, centroid, second_moment);
    if (surface) *surface = std::move(f);
  } else if (surface) {
    *surface = FoldedSurface{false, c0, {}};  // what foldedSurface(n, at) finds: the same sums decide
  }
}

}  // namespace tessella::detail
