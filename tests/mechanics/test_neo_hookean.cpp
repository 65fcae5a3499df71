// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The neo-Hookean membrane law (incompressible thin sheet with a fibre term,
// docs/mechanics.md "Membrane materials"): its stress and tangent against
// finite differences of its energy, its small-strain limit against St
// Venant-Kirchhoff (nu = 1/2, E = 3 mu) to first order, the uniaxial moduli
// ratio of the fibre term, the model's derivatives, and an inflated sphere
// against the closed form P = 2 (t / R) mu (1/lambda - 1/lambda^7) at several
// pressures, converging under refinement, with Newton converging quadratically.
#include <catch2/catch.hpp>

#include "membrane_derivatives.hpp"
#include "membrane_strains.hpp"
#include "surface_meshes.hpp"
#include "tessella/mechanics/equilibrium.hpp"
#include "tessella/mechanics/membrane_model.hpp"
#include "tessella/tissue/errors.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

using namespace tessella;
using namespace tessella::mechanics;

using test::supports;
using test::gradientOf;
using test::inPlane;
using test::Mat32;

namespace {

MembraneMaterial neoHookean(double young, double thickness, double ratio) {
  MembraneMaterial m;
  m.law = MembraneLaw::NeoHookean;
  m.young = young;
  m.thickness = thickness;
  m.fibre_ratio = ratio;
  return m;
}

// The stable stretch of the inflated incompressible neo-Hookean sphere:
// p = P R / (2 t mu) = 1/lambda - 1/lambda^7 on (1, 7^(1/6)), by bisection.
double sphereStretch(double p) {
  double lo = 1.0, hi = std::pow(7.0, 1.0 / 6.0);
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (1 / mid - std::pow(mid, -7) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("neo-Hookean law: stress and tangent are the derivatives of its energy", "[mechanics][neo-hookean]") {
  for (double ratio : {1.0, 6.0}) {
    const MembraneElementLaw law = MembraneElementLaw::of(neoHookean(3.0, 0.1, ratio), 1.7);
    CHECK(law.mu == Approx(1.7));
    CHECK(law.kappa == Approx(4 * 1.7 * (ratio - 1)));
    // Large strains of both signs, shear included.
    for (const Eigen::Vector3d& eps : {Eigen::Vector3d(0.3, -0.2, 0.25), Eigen::Vector3d(-0.3, 0.6, -0.4),
                                      Eigen::Vector3d(1.2, 0.05, 0.3)}) {
      CAPTURE(ratio, eps.transpose());
      const MembraneResponse r = law.at(gradientOf(eps), true);
      const double h = 1e-6;
      for (int i = 0; i < 3; ++i) {
        Eigen::Vector3d ep = eps, em = eps;
        ep(i) += h;
        em(i) -= h;
        const MembraneResponse rp = law.at(gradientOf(ep), false), rm = law.at(gradientOf(em), false);
        CHECK((rp.energy - rm.energy) / (2 * h) == Approx(r.stress(i)).epsilon(1e-7).margin(1e-9));
        CHECK(((rp.stress - rm.stress) / (2 * h) - r.tangent.col(i)).norm() < 1e-7 * r.tangent.norm());
      }
      CHECK((r.tangent - r.tangent.transpose()).norm() < 1e-13 * r.tangent.norm());
      // The closed form W = mu/2 (tr C + 1/det C - 3) + kappa/8 (C11 - 1)^2, evaluated directly.
      const double c11 = 1 + 2 * eps(0), c22 = 1 + 2 * eps(1), c12 = eps(2);
      const double det = c11 * c22 - c12 * c12;
      CHECK(r.energy == Approx(0.5 * law.mu * (c11 + c22 + 1 / det - 3) +
                               law.kappa / 8 * (c11 - 1) * (c11 - 1)).epsilon(1e-12));
    }
  }
  // A collapsed triangle has no finite energy.
  Mat32 flat = Mat32::Zero();
  flat(0, 0) = 1.0;
  CHECK(std::isinf(MembraneElementLaw::of(neoHookean(3.0, 0.1, 1.0)).at(flat, false).energy));
}

TEST_CASE("neo-Hookean law: at small strains it is St Venant-Kirchhoff with nu = 1/2 and E = 3 mu, to first order",
          "[mechanics][neo-hookean]") {
  const MembraneMaterial nh = neoHookean(3.0, 0.1, 1.0);
  MembraneMaterial svk = nh;
  svk.law = MembraneLaw::StVenantKirchhoff;
  svk.poisson = 0.5;
  const MembraneElementLaw a = MembraneElementLaw::of(nh), b = MembraneElementLaw::of(svk);
  // The tangents at rest are equal: mu [[4, 2, 0], [2, 4, 0], [0, 0, 1]].
  const Eigen::Matrix3d at_rest = a.at(Mat32::Identity(), true).tangent;
  CHECK((at_rest - svk.planeStressMatrix()).norm() < 1e-14 * at_rest.norm());
  CHECK((nh.smallStrainMatrix() - svk.planeStressMatrix()).norm() < 1e-14 * at_rest.norm());
  // The stresses differ at second order in the strain, the energies at third:
  // the relative differences fall tenfold when the strain does.
  const Eigen::Vector3d direction(0.8, -0.3, 0.5);
  std::vector<double> stress_gap, energy_gap;
  for (double s : {1e-2, 1e-3, 1e-4}) {
    const Mat32 F = gradientOf(s * direction);
    const MembraneResponse ra = a.at(F, false), rb = b.at(F, false);
    stress_gap.push_back((ra.stress - rb.stress).norm() / rb.stress.norm());
    energy_gap.push_back(std::abs(ra.energy - rb.energy) / rb.energy);
    std::cout << "neo-Hookean vs SVK (nu 1/2): strain " << s << "  relative stress gap " << stress_gap.back()
              << "  relative energy gap " << energy_gap.back() << "\n";
  }
  for (std::size_t k = 0; k + 1 < stress_gap.size(); ++k) {
    CHECK(stress_gap[k + 1] / stress_gap[k] == Approx(0.1).epsilon(0.05));
    CHECK(energy_gap[k + 1] / energy_gap[k] == Approx(0.1).epsilon(0.05));
  }
  CHECK(stress_gap.back() < 1e-3);
}

TEST_CASE("neo-Hookean law: the fibre term makes the small-strain moduli along and across the fibres r to 1",
          "[mechanics][neo-hookean]") {
  for (double ratio : {1.0, 2.5, 10.0}) {
    const MembraneMaterial m = neoHookean(3.0, 0.1, ratio);
    const Eigen::Matrix3d D = MembraneElementLaw::of(m).at(Mat32::Identity(), true).tangent;
    // Uniaxial stress (the other in-plane stress free): E1 = 1 / (D^-1)_11, E2 = 1 / (D^-1)_22.
    const Eigen::Matrix3d compliance = D.inverse();
    const double e1 = 1 / compliance(0, 0), e2 = 1 / compliance(1, 1), mu = m.shearModulus();
    CAPTURE(ratio);
    CHECK(e1 / e2 == Approx(ratio).epsilon(1e-13));
    CHECK(e1 == Approx(mu * (4 * ratio - 1)).epsilon(1e-13));
    CHECK((D - m.smallStrainMatrix()).norm() < 1e-13 * D.norm());
  }
  MembraneMaterial soft = neoHookean(3.0, 0.1, 0.5);
  CHECK_THROWS_WITH(soft.check(), Catch::Contains("fibre_ratio 0.5") && Catch::Contains("neo_hookean"));
  soft.fibre_ratio = 1.0;
  soft.poisson = 0.7;  // not used by the neo-Hookean law
  CHECK_NOTHROW(soft.check());
}

TEST_CASE("neo-Hookean membrane: gradient and Hessian equal finite differences (fibres, deformed, pressurised)",
          "[mechanics][neo-hookean]") {
  const test::SurfaceMesh m = test::capsuleMesh(1.0, 2.0, 2, 3, 6);
  std::vector<Vec3> fibres;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t e = 0; e < m.triangles.size(); ++e) fibres.emplace_back(u(rng), u(rng), u(rng));
  const MembraneModel model(m.points, m.triangles, neoHookean(1000.0, 0.01, 8.0), 0.7, fibres);
  Eigen::VectorXd x = model.referenceDofs();
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += 0.08 * u(rng);
  test::checkMembraneDerivatives(model, x);
}

TEST_CASE("neo-Hookean membrane: an inflated sphere follows P = 2 (t/R) mu (1/lambda - 1/lambda^7); "
          "errors fall under refinement; Newton converges quadratically",
          "[mechanics][neo-hookean]") {
  // Equibiaxial stretch lambda: S = mu (1 - lambda^-6), the tension
  // N = (t / J) lambda^2 S = t mu (1 - lambda^-6) = P r / 2 with r = lambda R.
  const double R = 1.0, E = 30.0, t = 0.01;
  const MembraneMaterial material = neoHookean(E, t, 1.0);
  const double mu = material.shearModulus();
  const std::vector<double> loads = {0.2, 0.4, 0.55};  // P R / (2 t mu); the limit load is 0.6197 at lambda 1.383
  std::vector<std::vector<double>> radius_errors(loads.size()), tension_errors(loads.size());
  std::vector<double> sizes;
  int quadratic_checks = 0;
  double worst_constant = 0.0;  // the largest r_{k+1} / r_k^2
  for (int level : {1, 2, 4}) {
    const test::SurfaceMesh m = test::sphereMesh(R, 6 * level - 1, 12 * level);
    sizes.push_back(2 * std::numbers::pi * R / (12 * level));
    MembraneModel model(m.points, m.triangles, material, 0.0);
    Eigen::VectorXd x = model.referenceDofs();
    for (std::size_t k = 0; k < loads.size(); ++k) {  // load stepping: each pressure from the last equilibrium
      const double P = loads[k] * 2 * t * mu / R;
      model.setPressure(P);
      EquilibriumOptions options;
      options.relative_tolerance = 1e-13;
      const EquilibriumReport report = solveEquilibrium(model, x, supports(m), options);
      const double lambda = sphereStretch(loads[k]);
      // The radius: mean distance of the points from the centre (midway between the poles, on the axis).
      const Eigen::Vector3d centre = 0.5 * (x.segment<3>(0) + x.segment<3>(3));
      double radius = 0.0;
      for (std::size_t i = 0; i < m.points.size(); ++i) radius += (x.segment<3>(3 * i) - centre).norm();
      radius /= static_cast<double>(m.points.size());
      radius_errors[k].push_back(std::abs(radius / (lambda * R) - 1));
      // Area-weighted mean of the two principal tensions against t mu (1 - lambda^-6).
      const double N_exact = t * mu * (1 - std::pow(lambda, -6));
      CHECK(N_exact == Approx(P * lambda * R / 2).epsilon(1e-12));
      double sum = 0.0, area = 0.0;
      for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        const auto& tri = m.triangles[e];
        const double a = 0.5 * (x.segment<3>(3 * tri[1]) - x.segment<3>(3 * tri[0]))
                                   .cross(x.segment<3>(3 * tri[2]) - x.segment<3>(3 * tri[0]))
                                   .norm();
        const Eigen::Vector2d n = inPlane(model.tension(x, e));
        sum += a * 0.5 * (std::abs(n[0] / N_exact - 1) + std::abs(n[1] / N_exact - 1));
        area += a;
      }
      tension_errors[k].push_back(sum / area);
      // Newton near the solution: each step squares the relative residual (up to a bounded factor,
      // measured 13..344: the sphere's tangent is soft across itself), down to the round-off floor.
      const double floor = report.roundoff_floor / report.force_scale;
      for (std::size_t i = 0; i + 1 < report.residuals.size(); ++i) {
        const double ri = report.residuals[i] / report.force_scale, rn = report.residuals[i + 1] / report.force_scale;
        if (ri < 1e-4 && ri > 1e-10) {
          ++quadratic_checks;
          if (rn > 10 * floor) worst_constant = std::max(worst_constant, rn / (ri * ri));
          CAPTURE(level, loads[k], i, ri, rn, floor);
          CHECK(rn <= 1000.0 * ri * ri + 4.0 * floor);
        }
      }
      if (level == 4 && k + 1 == loads.size())
        for (std::size_t i = 0; i < report.residuals.size(); ++i)
          std::cout << "neo-Hookean sphere, finest mesh, load " << loads[k] << ": relative residual " << i << " "
                    << report.residuals[i] / report.force_scale << "\n";
    }
  }
  std::cout << "neo-Hookean sphere: " << quadratic_checks << " Newton steps near the solution, largest r_{k+1} / r_k^2 "
            << worst_constant << "\n";
  CHECK(quadratic_checks >= 9);
  for (std::size_t k = 0; k < loads.size(); ++k) {
    for (std::size_t l = 0; l < sizes.size(); ++l)
      std::cout << "neo-Hookean sphere: load " << loads[k] << " (lambda " << sphereStretch(loads[k]) << ")  h "
                << sizes[l] << "  radius error " << radius_errors[k][l] << "  tension error "
                << tension_errors[k][l] << "\n";
    const double order = std::log(tension_errors[k][0] / tension_errors[k][2]) / std::log(sizes[0] / sizes[2]);
    std::cout << "neo-Hookean sphere: load " << loads[k] << "  observed order of the tension error " << order
              << "\n";
    CAPTURE(loads[k]);
    CHECK(radius_errors[k][2] < radius_errors[k][1]);
    CHECK(radius_errors[k][1] < radius_errors[k][0]);
    CHECK(tension_errors[k][2] < tension_errors[k][1]);
    CHECK(tension_errors[k][1] < tension_errors[k][0]);
    CHECK(radius_errors[k][2] < 5e-3);
    CHECK(tension_errors[k][2] < 0.02);
    CHECK(order > 1.5);
  }
}
