// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The 2D wall-spring and turgor model (docs/mechanics.md). Every wall w of a
// planar tissue (an edge between vertices a and b) is a linear elastic rod of
// rest length L0_w and stiffness S_w = E_w t_w (Young's modulus times wall
// thickness, per unit depth): tension T_w = S_w (L_w - L0_w) / L0_w, energy
// (1/2) (S_w / L0_w) (L_w - L0_w)^2. Every cell c pushes with its turgor
// pressure P_c on its area A_c. Total energy
//   E(x) = sum_w (1/2) k_w (L_w - L0_w)^2 - sum_c P_c A_c(x),   k_w = S_w / L0_w,
// with exact gradient and Hessian. Degrees of freedom: (x, y) of every vertex
// slot (planar_dofs.hpp), two per slot.

#include <cstdint>
#include <vector>

#include "tessella/mechanics/energy_model.hpp"
#include "tessella/tissue/handles.hpp"

namespace tessella {
class Tissue;
}

namespace tessella::mechanics {

struct WallSpring {
  Index a = 0;               ///< vertex (point) at one end
  Index b = 0;               ///< vertex at the other end
  double rest_length = 1.0;  ///< L0 > 0
  double stiffness = 1.0;    ///< S = E t > 0: the tension at strain 1
};

struct PressurisedCell {
  std::vector<Index> loop;  ///< vertex loop, counter-clockwise (positive area)
  double pressure = 0.0;    ///< turgor P
};

class WallSpringModel final : public EnergyModel {
 public:
  /// A model on `num_points` planar points (2 dofs each). Throws InputError
  /// naming the spring or cell for an index out of range, L0 or S not > 0, a
  /// loop of fewer than 3 points or a non-finite pressure.
  WallSpringModel(std::size_t num_points, std::vector<WallSpring> springs, std::vector<PressurisedCell> cells);

  /// The model of a planar 2D tissue: spring i is wall (edge) `walls[i]`, cell
  /// j is `cells[j]` with its face loop. Rest lengths, stiffnesses and pressures
  /// are per wall / cell slot (vectors indexed by the element index).
  static WallSpringModel fromTissue(const Tissue& tissue, const std::vector<double>& rest_length,
                                    const std::vector<double>& stiffness, const std::vector<double>& pressure);

  Eigen::Index size() const override { return static_cast<Eigen::Index>(2 * num_points_); }
  double energy(const Eigen::VectorXd& x) const override;
  void gradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) const override;
  void hessian(const Eigen::VectorXd& x, std::vector<Triplet>& entries) const override;
  double forceScale(const Eigen::VectorXd& x) const override;
  double energyScale(const Eigen::VectorXd& x) const override;

  const std::vector<WallSpring>& springs() const { return springs_; }
  const std::vector<PressurisedCell>& cells() const { return cells_; }
  /// The wall element index of spring i (fromTissue), else i.
  const std::vector<Index>& springElement() const { return spring_element_; }

  double length(const Eigen::VectorXd& x, std::size_t spring) const;
  /// (L - L0) / L0 of spring i.
  double strain(const Eigen::VectorXd& x, std::size_t spring) const;
  /// S (L - L0) / L0 of spring i.
  double tension(const Eigen::VectorXd& x, std::size_t spring) const;
  /// Signed area of cell j's loop (positive counter-clockwise).
  double area(const Eigen::VectorXd& x, std::size_t cell) const;

 private:
  std::size_t num_points_;
  std::vector<WallSpring> springs_;
  std::vector<PressurisedCell> cells_;
  std::vector<Index> spring_element_;
};

}  // namespace tessella::mechanics
