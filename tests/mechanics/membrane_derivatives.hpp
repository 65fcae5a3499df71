// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The membrane model's exact derivatives against central differences, shared
// by the tests of both membrane laws.

#include <catch2/catch.hpp>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tessella/mechanics/membrane_model.hpp"

namespace tessella::test {

/// At x: the gradient against central differences of the energy, the Hessian
/// against central differences of the gradient (both to 1e-6 of their
/// largest entry), the Hessian symmetric, and the gradient not negligible.
inline void checkMembraneDerivatives(const mechanics::MembraneModel& model, const Eigen::VectorXd& x) {
  Eigen::VectorXd g;
  model.gradient(x, g);
  std::vector<mechanics::Triplet> entries;
  model.hessian(x, entries);
  Eigen::SparseMatrix<double> H(model.size(), model.size());
  H.setFromTriplets(entries.begin(), entries.end());
  const Eigen::MatrixXd dense = H;
  CHECK((dense - dense.transpose()).lpNorm<Eigen::Infinity>() < 1e-12 * dense.lpNorm<Eigen::Infinity>());
  const double h = 1e-6;
  double worst_g = 0.0, worst_h = 0.0;
  Eigen::VectorXd gp, gm;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    Eigen::VectorXd xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    worst_g = std::max(worst_g, std::abs((model.energy(xp) - model.energy(xm)) / (2 * h) - g[i]));
    model.gradient(xp, gp);
    model.gradient(xm, gm);
    worst_h = std::max(worst_h, ((gp - gm) / (2 * h) - dense.col(i)).lpNorm<Eigen::Infinity>());
  }
  CHECK(worst_g < 1e-6 * g.lpNorm<Eigen::Infinity>());
  CHECK(worst_h < 1e-6 * dense.lpNorm<Eigen::Infinity>());
  CHECK(g.lpNorm<Eigen::Infinity>() > 1e-2);
}

}  // namespace tessella::test
