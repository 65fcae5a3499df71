// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The interface the equilibrium solver minimises: a total energy E(x) of a
// vector of degrees of freedom (positions), with its exact gradient and
// Hessian. Models: WallSpringModel (2D walls as springs, cells under turgor).

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace tessella::mechanics {

using Triplet = Eigen::Triplet<double>;

class EnergyModel {
 public:
  virtual ~EnergyModel() = default;

  /// Number of degrees of freedom (the length of x).
  virtual Eigen::Index size() const = 0;
  /// E(x): elastic energy minus pressure work.
  virtual double energy(const Eigen::VectorXd& x) const = 0;
  /// g = dE/dx (the out-of-balance force, with a minus sign), resized to size().
  virtual void gradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) const = 0;
  /// Appends the entries of the Hessian d2E/dx2 (symmetric, both triangles;
  /// repeated entries add up).
  virtual void hessian(const Eigen::VectorXd& x, std::vector<Triplet>& entries) const = 0;
  /// A force scale for the convergence test: the norm of the per-dof sums of
  /// the magnitudes of every force contribution at x (so that a relative
  /// residual of 1e-10 means "balanced to 10 digits of the forces involved").
  virtual double forceScale(const Eigen::VectorXd& x) const = 0;
  /// A scale of the energy's terms at x (the sum of their magnitudes): changes
  /// of E below a few ulps of it are round-off.
  virtual double energyScale(const Eigen::VectorXd& x) const = 0;
};

}  // namespace tessella::mechanics
