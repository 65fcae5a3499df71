#pragma once
// Measure kernels shared by the per-element queries and the batched
// recompute: one implementation, so a cached value is bit-identical to a
// direct query. Internal to the tissue module.

#include <cmath>
#include <span>

#include "tessella/tissue/geometry.hpp"

namespace tessella::detail {

// Loop of n points read through `at(i)`. See geometry.hpp for the definition.
template <typename At>
inline void polygonKernel(std::size_t n, At at, bool planar, bool moments, double& area,
                          Vec3& centroid, Vec3& normal, Mat3* second_moment) {
  if (planar) {
    // Shoelace in the z = 0 plane, one pass, about the first vertex (any
    // origin gives the same exact result; a local one keeps it well conditioned).
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
      if (moments) {
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
    if (moments && second_moment) {
      Mat3 m = Mat3::Zero();
      m(0, 0) = s * ixx / 12 - area * gx * gx;
      m(1, 1) = s * iyy / 12 - area * gy * gy;
      m(0, 1) = m(1, 0) = s * ixy / 24 - area * gx * gy;
      *second_moment = m;
    }
    return;
  }
  Vec3 c0 = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) c0 += at(i);
  c0 /= static_cast<double>(n);
  // General (surface or 3D wall): signed fan from the vertex mean.
  Vec3 vec_area = Vec3::Zero();
  Vec3 p = at(n - 1) - c0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 q = at(i) - c0;
    vec_area += p.cross(q);
    p = q;
  }
  const double len = vec_area.norm();
  normal = len > 0 ? Vec3(vec_area / len) : Vec3::Zero();
  double a = 0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  p = at(n - 1) - c0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 q = at(i) - c0;
    const Vec3 t = p.cross(q);
    const double tn = t.norm();
    const double ti = 0.5 * (t.dot(normal) < 0 ? -tn : tn);
    a += ti;
    first += ti * (p + q) / 3.0;
    if (moments) {
      const Vec3 s = p + q;
      second += (ti / 12.0) * (p * p.transpose() + q * q.transpose() + s * s.transpose());
    }
    p = q;
  }
  area = a;
  const Vec3 g = a != 0 ? Vec3(first / a) : Vec3::Zero();
  centroid = c0 + g;
  if (moments && second_moment) *second_moment = second - a * g * g.transpose();
}

}  // namespace tessella::detail
