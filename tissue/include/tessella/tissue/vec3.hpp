// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Small fixed-size linear algebra used by the geometry: Eigen types, plus a
// compact symmetric 3x3 tensor for per-element second moments.

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace tessella {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Symmetric 3x3 tensor stored as its 6 independent entries
/// (xx, yy, zz, xy, xz, yz): half the memory of a Mat3 in per-cell arrays.
struct Sym3 {
  std::array<double, 6> v{};  // xx yy zz xy xz yz

  static Sym3 fromMatrix(const Mat3& m) {
    return {{m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2)}};
  }
  Mat3 matrix() const {
    Mat3 m;
    m << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
    return m;
  }
};

/// A plane through `point` with normal `normal` (need not be unit length).
/// The positive side is the one `normal` points to.
struct Plane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitX();
  double signedDistance(const Vec3& p) const { return normal.normalized().dot(p - point); }
};

}  // namespace tessella
