// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Kinematics of a constant-strain membrane triangle, shared by the two
// membrane models: the deformation gradient F (3 x 2, from the rest frame to
// space), the Green-Lagrange strain and the strain-displacement matrices.
// Internal to the mechanics module.

#include <Eigen/Core>

#include "tessella/tissue/handles.hpp"

namespace tessella::mechanics::detail {

using Mat32 = Eigen::Matrix<double, 3, 2>;

/// The matrix of v x (.).
inline Eigen::Matrix3d cross(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

/// Vertex i of a flat dof vector (x0, y0, z0, x1, ...).
inline Eigen::Vector3d point(const Eigen::VectorXd& x, Index i) {
  return x.segment<3>(3 * static_cast<Eigen::Index>(i));
}

/// Green-Lagrange strain in Voigt form (E11, E22, 2 E12).
inline Eigen::Vector3d greenStrain(const Mat32& F) {
  const Eigen::Matrix2d C = F.transpose() * F;
  return {0.5 * (C(0, 0) - 1.0), 0.5 * (C(1, 1) - 1.0), C(0, 1)};
}

/// Strain-displacement matrix of a node with shape-function gradient g: d eps = B d x.
inline Eigen::Matrix3d strainMatrix(const Mat32& F, const Eigen::Vector2d& g) {
  Eigen::Matrix3d B;
  B.row(0) = g(0) * F.col(0).transpose();
  B.row(1) = g(1) * F.col(1).transpose();
  B.row(2) = g(0) * F.col(1).transpose() + g(1) * F.col(0).transpose();
  return B;
}

/// The symmetric 2 x 2 tensor of a Voigt vector (S11, S22, S12).
inline Eigen::Matrix2d stressTensor(const Eigen::Vector3d& s) {
  Eigen::Matrix2d S;
  S << s(0), s(2), s(2), s(1);
  return S;
}

}  // namespace tessella::mechanics::detail
