// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Cell-level (compartment) transport: one well-mixed concentration per cell,
// exchange across walls, no mesh. For a wall between cells i and j with area
// (length in 2D) A and permeability P, and optional polar (active) transport
// rates T_ij (pumping i -> j) and T_ji:
//   V_i dc_i/dt = sum_walls [ P A (c_j - c_i) - T_ij A c_i + T_ji A c_j ] - k_i V_i c_i + p_i V_i
// Written for amounts, every wall term leaves cell i exactly what enters cell
// j, so the total sum_i V_i c_i is conserved by implicit Euler and
// Crank-Nicolson alike (to round-off) when k = p = 0.

#include "tessella/solvers/diffusion_reaction.hpp"  // TimeScheme

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <vector>

namespace tessella::solvers {

struct CompartmentWall {
  int cell_i = -1;
  int cell_j = -1;
  double area = 0.0;          ///< wall area (3D) or length (2D), >= 0
  double permeability = 0.0;  ///< passive, symmetric, >= 0
  double polar_ij = 0.0;      ///< active transport rate from i to j (per unit area), >= 0
  double polar_ji = 0.0;      ///< active transport rate from j to i, >= 0
};

struct CompartmentNetwork {
  Eigen::VectorXd volume;  ///< per cell, > 0 (area for a 2D tissue)
  std::vector<CompartmentWall> walls;
  Eigen::VectorXd decay;       ///< per cell, >= 0; empty means none
  Eigen::VectorXd production;  ///< per cell (concentration per time); empty means none
};

class CompartmentTransport {
 public:
  /// Validates the network (throws InvalidProblemError naming the bad entry).
  explicit CompartmentTransport(CompartmentNetwork network, TimeScheme scheme = TimeScheme::ImplicitEuler);

  int numCells() const { return static_cast<int>(network_.volume.size()); }
  /// dc/dt at concentrations c.
  Eigen::VectorXd rate(const Eigen::VectorXd& c) const;
  /// Advances c by one step dt (sparse LU, refactorised only when dt changes).
  void step(Eigen::VectorXd& c, double dt);
  /// ceil(duration / dt) equal steps covering exactly `duration`.
  void advance(Eigen::VectorXd& c, double duration, double dt);
  /// sum_i V_i c_i.
  double totalAmount(const Eigen::VectorXd& c) const;

 private:
  CompartmentNetwork network_;
  TimeScheme scheme_;
  Eigen::SparseMatrix<double> B_;  // amount rates: d(V c)/dt = B c + s; columns of the wall part sum to 0
  Eigen::VectorXd source_;         // p_i V_i
  double factor_dt_ = 0.0;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
};

}  // namespace tessella::solvers
