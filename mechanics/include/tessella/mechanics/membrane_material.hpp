// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The material of a membrane triangle (docs/mechanics.md, "Membrane
// materials"): its law (St Venant-Kirchhoff, or the incompressible thin-sheet
// neo-Hookean with a fibre term), Young's modulus, Poisson's ratio, thickness
// and fibre ratio, and the law's response at a deformation gradient F (3 x 2,
// from the rest fibre frame to space): the strain energy per unit rest volume
// W, the second Piola-Kirchhoff stress S = dW/dE and its tangent dS/dE, in
// Voigt form (11 along the fibre, 22 across, 12 shear; strains with 2 E12).

#include <Eigen/Core>

#include "tessella/tissue/enum_table.hpp"

namespace tessella::mechanics {

enum class MembraneLaw {
  /// S = Q E, Q the transversely isotropic plane-stress law (planeStressMatrix).
  StVenantKirchhoff,
  /// W = mu/2 (tr C + 1/det C - 3) + kappa/8 (C11 - 1)^2, mu = E/3, kappa = 4 mu (fibre_ratio - 1).
  NeoHookean,
  /// W = mu/2 (tr C - 2 - ln det C) + lambda/8 (ln det C)^2 + kappa/8 (C11 - 1)^2: the compressible
  /// neo-Hookean sheet with the plane-stress Lame constants of E and nu, mu = E / (2 (1 + nu)),
  /// lambda = E nu / (1 - nu^2), kappa = (fibre_ratio - 1) E / (1 - nu^2).
  CompressibleNeoHookean,
};

/// The names of the laws (`mechanics.material`): st_venant_kirchhoff, neo_hookean,
/// compressible_neo_hookean.
const EnumTable<MembraneLaw>& membraneLaws();

struct MembraneMaterial {
  double young = 1.0;        ///< E > 0 (St Venant-Kirchhoff: across the fibres; neo-Hookean: 3 mu)
  double poisson = 0.3;      ///< nu in (-1, 0.5]; nu^2 < fibre_ratio (not used by the incompressible neo-Hookean)
  double thickness = 1.0;    ///< t > 0 (the rest thickness)
  double fibre_ratio = 1.0;  ///< > 0 (neo-Hookean laws: >= 1); 1: isotropic
  MembraneLaw law = MembraneLaw::StVenantKirchhoff;

  /// The plane-stress law in the fibre frame (Voigt: 11 along the fibre, 22
  /// across, 12 shear): E1 = ratio E, E2 = E, nu12 = nu, nu21 = nu / ratio,
  /// G12 = E / (2 (1 + nu)); isotropic plane stress at ratio 1. (St
  /// Venant-Kirchhoff's Q; the neo-Hookean law's tangent at rest is
  /// smallStrainMatrix().)
  Eigen::Matrix3d planeStressMatrix() const;
  /// dS/dE at E = 0 of the law: planeStressMatrix() for St Venant-Kirchhoff;
  /// neo-Hookean: mu [[4 + k, 2, 0], [2, 4, 0], [0, 0, 1]], k = kappa / mu;
  /// compressible neo-Hookean: [[lambda + 2 mu + kappa, lambda, 0], [lambda, lambda + 2 mu, 0], [0, 0, mu]],
  /// planeStressMatrix() at fibre_ratio 1.
  Eigen::Matrix3d smallStrainMatrix() const;
  /// The neo-Hookean shear modulus: mu = E / 3 (incompressible: nu = 1/2), or
  /// E / (2 (1 + nu)) for the compressible law.
  double shearModulus() const {
    return law == MembraneLaw::CompressibleNeoHookean ? young / (2.0 * (1.0 + poisson)) : young / 3.0;
  }
  /// The compressible law's plane-stress Lame constant lambda = E nu / (1 - nu^2) (0 for the others).
  double lameLambda() const {
    return law == MembraneLaw::CompressibleNeoHookean ? young * poisson / (1.0 - poisson * poisson) : 0.0;
  }
  /// The fibre stiffness kappa = (fibre_ratio - 1) (lambda + 2 mu): 4 mu (r - 1)
  /// for the incompressible law (lambda = 0 there, its D11 at rest is 4 mu),
  /// (r - 1) E / (1 - nu^2) for the compressible one. The small-strain uniaxial
  /// moduli along and across the fibres are then in the ratio r.
  double fibreStiffness() const {
    const double along = law == MembraneLaw::CompressibleNeoHookean ? lameLambda() + 2.0 * shearModulus()
                                                                     : 4.0 * shearModulus();
    return along * (fibre_ratio - 1.0);
  }
  /// Throws InputError naming the parameter and its value when out of range.
  void check() const;
};

/// The response of one triangle's law at F.
struct MembraneResponse {
  double energy = 0.0;              ///< W per unit rest volume (+inf for a collapsed triangle, det C <= 0)
  Eigen::Vector3d stress = Eigen::Vector3d::Zero();   ///< S (S11, S22, S12)
  Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();  ///< dS/dE, Voigt (strain (E11, E22, 2 E12)); when asked
};

/// A law's constants for one triangle, Young's modulus scaled: St
/// Venant-Kirchhoff's Q, the neo-Hookean mu and kappa (and the compressible
/// law's lambda).
struct MembraneElementLaw {
  MembraneLaw law = MembraneLaw::StVenantKirchhoff;
  Eigen::Matrix3d q = Eigen::Matrix3d::Zero();
  double mu = 0.0;
  double kappa = 0.0;
  double lambda = 0.0;

  /// The constants of `material` with E scaled by young_scale (Q = young_scale Q(material)).
  static MembraneElementLaw of(const MembraneMaterial& material, double young_scale = 1.0);
  /// W, S and (with `tangent`) dS/dE at F (3 x 2, in the rest fibre frame).
  MembraneResponse at(const Eigen::Matrix<double, 3, 2>& F, bool tangent) const;
};

}  // namespace tessella::mechanics
