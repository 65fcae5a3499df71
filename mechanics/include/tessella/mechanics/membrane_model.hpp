// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Membrane finite elements on a closed triangulated surface under internal
// pressure (docs/mechanics.md, "Membranes"): constant-strain triangles, large
// deformation, St Venant-Kirchhoff with a transversely isotropic plane-stress
// law or neo-Hookean with a fibre term (membrane_material.hpp; fibre direction
// per triangle). Total energy
//   E(x) = sum_e t A0_e W(E_e) - P V(x),
// E_e the Green-Lagrange strain of triangle e in its reference fibre frame
// (St Venant-Kirchhoff: W = (1/2) eps^T Q eps, eps = (E11, E22, 2 E12)), V the
// volume the surface encloses. Degrees of
// freedom: (x, y, z) of every point, three per point.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "tessella/mechanics/energy_model.hpp"
#include "tessella/mechanics/membrane_material.hpp"
#include "tessella/mechanics/membrane_triangle.hpp"
#include "tessella/mechanics/strain_growth.hpp"
#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::mechanics {


class MembraneModel final : public EnergyModel {
 public:
  /// `reference`: the rest positions (the stress-free shape); `triangles`
  /// listed counter-clockwise seen from outside (the enclosed volume is then
  /// positive); `fibres`: one direction per triangle (projected on its plane;
  /// empty or a direction normal to the triangle: its first edge).
  /// Throws InputError naming the triangle for a bad index or a degenerate one.
  MembraneModel(std::vector<Vec3> reference, std::vector<std::array<Index, 3>> triangles, MembraneMaterial material,
                double pressure, const std::vector<Vec3>& fibres = {});

  Eigen::Index size() const override { return static_cast<Eigen::Index>(3 * reference_.size()); }
  double energy(const Eigen::VectorXd& x) const override;
  void gradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) const override;
  void hessian(const Eigen::VectorXd& x, std::vector<Triplet>& entries) const override;
  double forceScale(const Eigen::VectorXd& x) const override;
  double energyScale(const Eigen::VectorXd& x) const override;

  /// The reference positions as a dof vector.
  Eigen::VectorXd referenceDofs() const;
  /// Volume enclosed by the surface at x (divergence theorem).
  double volume(const Eigen::VectorXd& x) const;
  /// Membrane tension of triangle e at x: the Cauchy stress times the
  /// reference thickness, N = (t / J) F S F^T (force per unit current length;
  /// a 3x3 tensor in the triangle's current plane), J its area ratio.
  Eigen::Matrix3d tension(const Eigen::VectorXd& x, std::size_t e) const;
  const std::vector<std::array<Index, 3>>& triangles() const { return triangles_; }
  double pressure() const { return pressure_; }
  void setPressure(double pressure);

  /// Lockhart-Ortega growth of every triangle's rest shape over dt at the
  /// strains of x: along each principal direction of its stretch (the
  /// eigenvectors of C = F^T F in the reference), with principal stretch
  /// lambda_i, the rest shape grows by exp(law.relativeRate(lambda_i - 1) dt)
  /// (the strain of the 2D walls, (L - L0) / L0, taken along the principal
  /// directions). After growth the rest shapes need not fit together:
  /// referenceDofs() stays the initial shape. Returns the largest relative rate.
  double growRestShape(const Eigen::VectorXd& x, const StrainGrowthLaw& law, double dt);
  /// Reference (rest) area of triangle e.
  double restArea(std::size_t e) const { return elements_[e].area; }

 private:
  using Element = MembraneTriangleRest;
  Eigen::Matrix<double, 3, 2> deformationGradient(const Eigen::VectorXd& x, std::size_t e) const;

  std::vector<Vec3> reference_;
  std::vector<std::array<Index, 3>> triangles_;
  MembraneMaterial material_;
  MembraneElementLaw law_;
  double pressure_;
  std::vector<Element> elements_;
};

}  // namespace tessella::mechanics
