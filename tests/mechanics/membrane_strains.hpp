// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Strains and tensions of one membrane element, shared by the membrane laws'
// tests: a deformation gradient of a given Green strain, and the in-plane
// principal values of a tension tensor.

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>

namespace tessella::test {

using Mat32 = Eigen::Matrix<double, 3, 2>;

/// A deformation gradient (3 x 2) whose Green strain is eps (Voigt: E11, E22, 2 E12),
/// rotated into space by an arbitrary rotation: F = R_3x2 U, U = sqrt(C).
inline Mat32 gradientOf(const Eigen::Vector3d& eps) {
  Eigen::Matrix2d C;
  C << 1 + 2 * eps(0), eps(2), eps(2), 1 + 2 * eps(1);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(C);
  const Eigen::Matrix2d U = eig.operatorSqrt();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  return R.leftCols<2>() * U;
}

/// The two in-plane principal values of a membrane tension tensor (3 x 3, rank 2).
inline Eigen::Vector2d inPlane(const Eigen::Matrix3d& N) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(N);
  const Eigen::Vector3d v = eig.eigenvalues();
  int drop = 0;  // the normal direction: the eigenvalue of smallest magnitude
  for (int i = 1; i < 3; ++i)
    if (std::abs(v[i]) < std::abs(v[drop])) drop = i;
  Eigen::Vector2d out;
  for (int i = 0, k = 0; i < 3; ++i)
    if (i != drop) out[k++] = v[i];
  return out;
}

}  // namespace tessella::test
