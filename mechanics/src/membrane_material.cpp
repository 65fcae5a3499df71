// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/membrane_material.hpp"

#include "membrane_kinematics.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <string>

namespace tessella::mechanics {

const EnumTable<MembraneLaw>& membraneLaws() {
  static const EnumTable<MembraneLaw> table(
      "membrane material",
      {{"st_venant_kirchhoff", MembraneLaw::StVenantKirchhoff,
        "St Venant-Kirchhoff: S = Q E, Q the transversely isotropic plane-stress law (young, poisson, "
        "fibre_ratio: E1 = fibre_ratio E along the fibres)."},
       {"neo_hookean", MembraneLaw::NeoHookean,
        "Incompressible thin-sheet neo-Hookean (mu = young / 3; poisson not used) with the standard fibre "
        "term kappa/8 (I4 - 1)^2, kappa = 4 mu (fibre_ratio - 1) (fibre_ratio >= 1)."},
       {"compressible_neo_hookean", MembraneLaw::CompressibleNeoHookean,
        "Compressible neo-Hookean sheet, W = mu/2 (tr C - 2 - ln det C) + lambda/8 (ln det C)^2, with the "
        "plane-stress constants of young and poisson (mu = E / (2 (1 + nu)), lambda = E nu / (1 - nu^2)): St "
        "Venant-Kirchhoff at small strains, and a triangle cannot be crushed to nothing; fibre term kappa/8 "
        "(I4 - 1)^2, kappa = (fibre_ratio - 1) E / (1 - nu^2) (fibre_ratio >= 1)."}});
  return table;
}

Eigen::Matrix3d MembraneMaterial::planeStressMatrix() const {
  const double e1 = fibre_ratio * young, e2 = young;
  const double nu12 = poisson, nu21 = poisson / fibre_ratio;
  const double d = 1.0 - nu12 * nu21;
  Eigen::Matrix3d q = Eigen::Matrix3d::Zero();
  q(0, 0) = e1 / d;
  q(1, 1) = e2 / d;
  q(0, 1) = q(1, 0) = nu12 * e2 / d;
  q(2, 2) = young / (2.0 * (1.0 + poisson));
  return q;
}

Eigen::Matrix3d MembraneMaterial::smallStrainMatrix() const {
  if (law == MembraneLaw::StVenantKirchhoff) return planeStressMatrix();
  const double mu = shearModulus();
  Eigen::Matrix3d d;
  if (law == MembraneLaw::CompressibleNeoHookean) {
    const double lambda = lameLambda();
    d << lambda + 2.0 * mu + fibreStiffness(), lambda, 0.0, lambda, lambda + 2.0 * mu, 0.0, 0.0, 0.0, mu;
    return d;
  }
  d << 4.0 * mu + fibreStiffness(), 2.0 * mu, 0.0, 2.0 * mu, 4.0 * mu, 0.0, 0.0, 0.0, mu;
  return d;
}

void MembraneMaterial::check() const {
  auto bad = [](const char* name, double v, const char* why) {
    throw InputError(std::string("membrane material: ") + name + " " + formatNumber(v) + " " + why);
  };
  if (!(young > 0.0 && std::isfinite(young))) bad("young", young, "must be > 0");
  if (!(thickness > 0.0 && std::isfinite(thickness))) bad("thickness", thickness, "must be > 0");
  if (!(fibre_ratio > 0.0 && std::isfinite(fibre_ratio))) bad("fibre_ratio", fibre_ratio, "must be > 0");
  if (law == MembraneLaw::NeoHookean) {
    // A negative fibre term would make W unbounded below along the fibres.
    if (!(fibre_ratio >= 1.0)) bad("fibre_ratio", fibre_ratio, "must be >= 1 for neo_hookean (fibres stiffen)");
    return;
  }
  if (!(poisson > -1.0 && poisson <= 0.5)) bad("poisson", poisson, "must be in (-1, 0.5]");
  if (law == MembraneLaw::CompressibleNeoHookean) {
    // nu = 1/2 is the incompressible limit only in 3D; the sheet's lambda stays finite up to nu < 1.
    if (!(fibre_ratio >= 1.0))
      bad("fibre_ratio", fibre_ratio, "must be >= 1 for compressible_neo_hookean (fibres stiffen)");
    return;
  }
  if (!(poisson * poisson < fibre_ratio)) bad("poisson", poisson, "squared must be below fibre_ratio");
}

MembraneElementLaw MembraneElementLaw::of(const MembraneMaterial& material, double young_scale) {
  MembraneElementLaw l;
  l.law = material.law;
  if (l.law == MembraneLaw::StVenantKirchhoff) {
    l.q = young_scale * material.planeStressMatrix();
  } else {
    l.mu = young_scale * material.shearModulus();
    l.kappa = young_scale * material.fibreStiffness();
    l.lambda = young_scale * material.lameLambda();
  }
  return l;
}

namespace {

// The in-plane Green strain E (Voigt: E11, E22, 2 E12) of both neo-Hookean
// laws, its invariants and delta = det C - 1 = 2 tr E + 4 det E, from the
// strain so that nothing cancels at small strains.
struct StrainInvariants {
  explicit StrainInvariants(const Eigen::Vector3d& eps)
      : e11(eps(0)), e22(eps(1)), e12(0.5 * eps(2)), tr(e11 + e22), det(e11 * e22 - e12 * e12),
        delta(2.0 * tr + 4.0 * det), J2(1.0 + delta) {}
  double e11, e22, e12, tr, det, delta;
  double J2;  // det C
};

// An inverted or collapsed element (det C <= 0): infinite energy, no stress.
MembraneResponse inverted(bool tangent) {
  MembraneResponse r;
  r.energy = std::numeric_limits<double>::infinity();
  r.stress.setConstant(std::numeric_limits<double>::quiet_NaN());
  if (tangent) r.tangent.setConstant(std::numeric_limits<double>::quiet_NaN());
  return r;
}

// Voigt index I -> the tensor index pair (i, j) of the tangents.
constexpr int kVoigtPairs[3][2] = {{0, 0}, {1, 1}, {0, 1}};

// delta - log(1 + delta), without the cancellation of the two at small delta (series below |delta| = 0.1,
// truncated where its terms fall below 1e-17 of the sum).
double deltaMinusLog1p(double delta) {
  if (std::abs(delta) >= 0.1) return delta - std::log1p(delta);
  double sum = 0.0, power = delta;
  for (int k = 2; k <= 18; ++k) {
    power *= delta;
    sum += (k % 2 == 0 ? 1.0 : -1.0) * power / k;
  }
  return sum;
}

MembraneResponse compressibleNeoHookean(double mu, double lambda, double kappa, const Eigen::Vector3d& eps,
                                        bool tangent) {
  // W = mu/2 (tr C - 2 - ln det C) + lambda/2 (ln J)^2 + kappa/2 E11^2, J = sqrt(det C); in E = (C - I)/2
  // with delta = det C - 1 = 2 tr E + 4 det E: tr C - 2 - ln det C = (delta - ln(1 + delta)) - 4 det E.
  //   S = mu (I - C^-1) + lambda ln J C^-1 + kappa E11 e1 e1,   I - C^-1 = 2 C^-1 E (no cancellation),
  //   dS/dE = lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) Isym(C^-1) + kappa e1 e1 e1 e1.
  MembraneResponse r;
  const StrainInvariants v(eps);
  if (!(v.J2 > 0.0)) return inverted(tangent);
  const double e11 = v.e11, e22 = v.e22, e12 = v.e12, det = v.det, delta = v.delta, J2 = v.J2;
  const double log_j = 0.5 * std::log1p(delta);
  r.energy = 0.5 * mu * (deltaMinusLog1p(delta) - 4.0 * det) + 0.5 * lambda * log_j * log_j + 0.5 * kappa * e11 * e11;
  Eigen::Matrix2d C, E;
  C << 1.0 + 2.0 * e11, 2.0 * e12, 2.0 * e12, 1.0 + 2.0 * e22;
  E << e11, e12, e12, e22;
  // C^-1 = adj(C) / det C, from the strain so that det C keeps its digits.
  Eigen::Matrix2d Ci;
  Ci << C(1, 1), -C(0, 1), -C(1, 0), C(0, 0);
  Ci /= J2;
  const Eigen::Matrix2d s = 2.0 * mu * Ci * E + lambda * log_j * Ci;
  r.stress = Eigen::Vector3d(s(0, 0) + kappa * e11, s(1, 1), 0.5 * (s(0, 1) + s(1, 0)));
  if (!tangent) return r;
  const double f = 2.0 * (mu - lambda * log_j);
  for (int I = 0; I < 3; ++I)
    for (int K = 0; K < 3; ++K) {
      const int i = kVoigtPairs[I][0], j = kVoigtPairs[I][1], k = kVoigtPairs[K][0], l = kVoigtPairs[K][1];
      r.tangent(I, K) = lambda * Ci(i, j) * Ci(k, l) + f * 0.5 * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
    }
  r.tangent(0, 0) += kappa;
  return r;
}

}  // namespace

MembraneResponse MembraneElementLaw::at(const Eigen::Matrix<double, 3, 2>& F, bool tangent) const {
  MembraneResponse r;
  const Eigen::Vector3d eps = detail::greenStrain(F);
  if (law == MembraneLaw::StVenantKirchhoff) {
    r.stress = q * eps;
    r.energy = 0.5 * eps.dot(r.stress);
    if (tangent) r.tangent = q;
    return r;
  }
  if (law == MembraneLaw::CompressibleNeoHookean) return compressibleNeoHookean(mu, lambda, kappa, eps, tangent);
  // Neo-Hookean, written in E = (C - I) / 2 so that nothing cancels at small
  // strains: with tr = tr E, det = det E, delta = det C - 1 = 2 tr + 4 det,
  //   W = mu (2 tr^2 + 4 tr det - 2 det) / det C + kappa / 2 E11^2,
  //   S = mu (I - adj(C) / det C^2) + kappa E11 e1 e1,
  //   I - adj(C) / det C^2 = [[2 delta + delta^2 - 2 E22, 2 E12], [2 E12, 2 delta + delta^2 - 2 E11]] / det C^2.
  const StrainInvariants v(eps);
  if (!(v.J2 > 0.0)) return inverted(tangent);
  const double e11 = v.e11, e22 = v.e22, e12 = v.e12, tr = v.tr, det = v.det, delta = v.delta, J2 = v.J2;
  const double common = 2.0 * delta + delta * delta;
  r.energy = mu * (2.0 * tr * tr + 4.0 * tr * det - 2.0 * det) / J2 + 0.5 * kappa * e11 * e11;
  r.stress = Eigen::Vector3d(mu * (common - 2.0 * e22), mu * (common - 2.0 * e11), mu * 2.0 * e12) / (J2 * J2);
  r.stress(0) += kappa * e11;
  if (!tangent) return r;
  // dS/dE = (2 mu / det C) [ (Ci_ik Ci_jl + Ci_il Ci_jk) / 2 + Ci_ij Ci_kl ] + kappa e1 e1 e1 e1.
  Eigen::Matrix2d C;
  C << 1.0 + 2.0 * e11, 2.0 * e12, 2.0 * e12, 1.0 + 2.0 * e22;
  const Eigen::Matrix2d Ci = C.inverse();
  const double f = 2.0 * mu / J2;
  for (int I = 0; I < 3; ++I)
    for (int K = 0; K < 3; ++K) {
      const int i = kVoigtPairs[I][0], j = kVoigtPairs[I][1], k = kVoigtPairs[K][0], l = kVoigtPairs[K][1];
      r.tangent(I, K) = f * (0.5 * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k)) + Ci(i, j) * Ci(k, l));
    }
  r.tangent(0, 0) += kappa;
  return r;
}

}  // namespace tessella::mechanics
