// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Template part of structured_meshes.hpp (error norms).

#include "tessella/solvers/element_geometry.hpp"

namespace tessella::test {

template <typename U, typename GradU>
ErrorNorms errorNorms(const mesh::FeMesh& mesh, const Eigen::VectorXd& uh, U&& u, GradU&& grad_u) {
  const Quadrature q = simplexQuadrature(mesh.dim);
  ErrorNorms err;
  const int n = mesh.dim + 1;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const solvers::ElementGeometry g = solvers::elementGeometry(mesh, e);
    Eigen::Vector3d grad_h = Eigen::Vector3d::Zero();
    for (int a = 0; a < n; ++a) grad_h += uh[mesh.elements(e, a)] * g.gradients.row(a).transpose();
    for (std::size_t k = 0; k < q.points.size(); ++k) {
      // Barycentric coordinates: lambda_a for a = 1..d from the point, lambda_0 = 1 - sum.
      double lambda[4];
      lambda[0] = 1.0;
      for (int a = 1; a < n; ++a) {
        lambda[a] = q.points[k][a - 1];
        lambda[0] -= lambda[a];
      }
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      double value_h = 0.0;
      for (int a = 0; a < n; ++a) {
        x += lambda[a] * mesh.nodes.row(mesh.elements(e, a)).transpose();
        value_h += lambda[a] * uh[mesh.elements(e, a)];
      }
      const double w = q.weights[k] * g.measure;
      const double d = value_h - u(x);
      err.l2 += w * d * d;
      err.h1 += w * (grad_h - grad_u(x)).squaredNorm();
    }
  }
  return err;
}

}  // namespace tessella::test
