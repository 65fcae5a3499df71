// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The compressible neo-Hookean membrane law (docs/mechanics.md "Membrane
// materials"): its stress and tangent against finite differences of its
// energy, its small-strain limit against St Venant-Kirchhoff with the same E
// and nu to first order, the uniaxial moduli ratio of the fibre term, the
// model's derivatives, and an inflated sphere against the closed form
// P = (2 t / (R lambda)) (mu (1 - lambda^-2) + 2 Lambda ln(lambda) / lambda^2).
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

MembraneMaterial compressible(double young, double poisson, double thickness, double ratio) {
  MembraneMaterial m;
  m.law = MembraneLaw::CompressibleNeoHookean;
  m.young = young;
  m.poisson = poisson;
  m.thickness = thickness;
  m.fibre_ratio = ratio;
  return m;
}

}  // namespace

TEST_CASE("compressible neo-Hookean law: stress and tangent are the derivatives of its energy",
          "[mechanics][neo-hookean]") {
  for (double ratio : {1.0, 6.0}) {
    const MembraneMaterial material = compressible(3.0, 0.3, 0.1, ratio);
    const MembraneElementLaw law = MembraneElementLaw::of(material, 1.7);
    const double mu = 1.7 * 3.0 / 2.6, lambda = 1.7 * 3.0 * 0.3 / 0.91;
    CHECK(law.mu == Approx(mu).epsilon(1e-14));
    CHECK(law.lambda == Approx(lambda).epsilon(1e-14));
    CHECK(law.kappa == Approx((ratio - 1) * 1.7 * 3.0 / 0.91).epsilon(1e-14).margin(1e-15));
    // Large strains of both signs, shear included, and small ones (the series branch of the energy).
    for (const Eigen::Vector3d& eps : {Eigen::Vector3d(0.3, -0.2, 0.25), Eigen::Vector3d(-0.3, 0.6, -0.4),
                                      Eigen::Vector3d(1.2, 0.05, 0.3), Eigen::Vector3d(0.02, -0.01, 0.03)}) {
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
      // The closed form W = mu/2 (tr C - 2 - ln det C) + lambda/8 (ln det C)^2 + kappa/8 (C11 - 1)^2, directly.
      const double c11 = 1 + 2 * eps(0), c22 = 1 + 2 * eps(1), c12 = eps(2);
      const double det = c11 * c22 - c12 * c12;
      CHECK(r.energy == Approx(0.5 * law.mu * (c11 + c22 - 2 - std::log(det)) +
                               law.lambda / 8 * std::log(det) * std::log(det) +
                               law.kappa / 8 * (c11 - 1) * (c11 - 1))
                            .epsilon(1e-10));
    }
  }
  // A collapsed triangle has no finite energy.
  Mat32 flat = Mat32::Zero();
  flat(0, 0) = 1.0;
  CHECK(std::isinf(MembraneElementLaw::of(compressible(3.0, 0.3, 0.1, 1.0)).at(flat, false).energy));
}

TEST_CASE("compressible neo-Hookean law: at small strains it is St Venant-Kirchhoff with its E and nu, to first "
          "order",
          "[mechanics][neo-hookean]") {
  for (double nu : {0.3, -0.2, 0.5}) {
    CAPTURE(nu);
    const MembraneMaterial cnh = compressible(3.0, nu, 0.1, 1.0);
    MembraneMaterial svk = cnh;
    svk.law = MembraneLaw::StVenantKirchhoff;
    const MembraneElementLaw a = MembraneElementLaw::of(cnh), b = MembraneElementLaw::of(svk);
    const Eigen::Matrix3d at_rest = a.at(Mat32::Identity(), true).tangent;
    CHECK((at_rest - svk.planeStressMatrix()).norm() < 1e-14 * at_rest.norm());
    CHECK((cnh.smallStrainMatrix() - svk.planeStressMatrix()).norm() < 1e-14 * at_rest.norm());
    const Eigen::Vector3d direction(0.8, -0.3, 0.5);
    std::vector<double> stress_gap, energy_gap;
    for (double s : {1e-2, 1e-3, 1e-4}) {
      const Mat32 F = gradientOf(s * direction);
      const MembraneResponse ra = a.at(F, false), rb = b.at(F, false);
      stress_gap.push_back((ra.stress - rb.stress).norm() / rb.stress.norm());
      energy_gap.push_back(std::abs(ra.energy - rb.energy) / rb.energy);
      std::cout << "compressible neo-Hookean vs SVK (nu " << nu << "): strain " << s << "  relative stress gap "
                << stress_gap.back() << "  relative energy gap " << energy_gap.back() << "\n";
    }
    for (std::size_t k = 0; k + 1 < stress_gap.size(); ++k) {
      CHECK(stress_gap[k + 1] / stress_gap[k] == Approx(0.1).epsilon(0.05));
      CHECK(energy_gap[k + 1] / energy_gap[k] == Approx(0.1).epsilon(0.05));
    }
    CHECK(stress_gap.back() < 1e-3);
  }
}

TEST_CASE("compressible neo-Hookean law: the fibre term makes the small-strain moduli along and across the fibres "
          "r to 1; bad parameters are refused",
          "[mechanics][neo-hookean]") {
  for (double ratio : {1.0, 2.5, 10.0}) {
    const MembraneMaterial m = compressible(3.0, 0.3, 0.1, ratio);
    const Eigen::Matrix3d D = MembraneElementLaw::of(m).at(Mat32::Identity(), true).tangent;
    const Eigen::Matrix3d compliance = D.inverse();
    const double e1 = 1 / compliance(0, 0), e2 = 1 / compliance(1, 1);
    CAPTURE(ratio);
    CHECK(e1 / e2 == Approx(ratio).epsilon(1e-13));
    CHECK(e2 == Approx(3.0 * (1 - 0.09 / ratio) / 0.91).epsilon(1e-13));  // E at ratio 1
    CHECK((D - m.smallStrainMatrix()).norm() < 1e-13 * D.norm());
  }
  CHECK_THROWS_WITH(compressible(3.0, 0.3, 0.1, 0.5).check(),
                    Catch::Contains("fibre_ratio 0.5") && Catch::Contains("compressible_neo_hookean"));
  CHECK_THROWS_WITH(compressible(3.0, 0.7, 0.1, 1.0).check(), Catch::Contains("poisson 0.7"));
  CHECK_NOTHROW(compressible(3.0, 0.5, 0.1, 1.0).check());
}

TEST_CASE("compressible neo-Hookean membrane: gradient and Hessian equal finite differences (fibres, deformed, "
          "pressurised)",
          "[mechanics][neo-hookean]") {
  const test::SurfaceMesh m = test::capsuleMesh(1.0, 2.0, 2, 3, 6);
  std::vector<Vec3> fibres;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t e = 0; e < m.triangles.size(); ++e) fibres.emplace_back(u(rng), u(rng), u(rng));
  const MembraneModel model(m.points, m.triangles, compressible(1000.0, 0.3, 0.01, 8.0), 0.7, fibres);
  Eigen::VectorXd x = model.referenceDofs();
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += 0.08 * u(rng);
  test::checkMembraneDerivatives(model, x);
}

// Equibiaxial stretch lambda: C = lambda^2 I, ln J = 2 ln lambda, S = (mu (1 - lambda^-2) + 2 Lambda ln(lambda)
// / lambda^2) I, the tension N = (t / J) lambda^2 S = t S = P r / 2 with r = lambda R. The pressure rises to a
// limit load P R / (2 t) = 6.674 at lambda = 1.559 (E = 30, nu = 0.3); the stretches below are short of it.
TEST_CASE("compressible neo-Hookean membrane: an inflated sphere reaches the closed-form radius and tension; "
          "errors fall under refinement",
          "[mechanics][neo-hookean]") {
  const double R = 1.0, E = 30.0, nu = 0.3, t = 0.01;
  const MembraneMaterial material = compressible(E, nu, t, 1.0);
  const double mu = E / (2 * (1 + nu)), Lambda = E * nu / (1 - nu * nu);
  auto tension = [&](double lambda) {
    return t * (mu * (1 - std::pow(lambda, -2)) + 2 * Lambda * std::log(lambda) / (lambda * lambda));
  };
  const std::vector<double> stretches = {1.05, 1.15, 1.3};
  std::vector<std::vector<double>> radius_errors(stretches.size()), tension_errors(stretches.size());
  std::vector<double> sizes;
  for (int level : {1, 2, 4}) {
    const test::SurfaceMesh m = test::sphereMesh(R, 6 * level - 1, 12 * level);
    sizes.push_back(2 * std::numbers::pi * R / (12 * level));
    MembraneModel model(m.points, m.triangles, material, 0.0);
    Eigen::VectorXd x = model.referenceDofs();
    for (std::size_t k = 0; k < stretches.size(); ++k) {  // load stepping: each pressure from the last equilibrium
      const double lambda = stretches[k];
      const double N_exact = tension(lambda);
      const double P = 2 * N_exact / (lambda * R);
      model.setPressure(P);
      EquilibriumOptions options;
      options.relative_tolerance = 1e-13;
      solveEquilibrium(model, x, supports(m), options);
      const Eigen::Vector3d centre = 0.5 * (x.segment<3>(0) + x.segment<3>(3));
      double radius = 0.0;
      for (std::size_t i = 0; i < m.points.size(); ++i) radius += (x.segment<3>(3 * i) - centre).norm();
      radius /= static_cast<double>(m.points.size());
      radius_errors[k].push_back(std::abs(radius / (lambda * R) - 1));
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
    }
  }
  for (std::size_t k = 0; k < stretches.size(); ++k) {
    for (std::size_t l = 0; l < sizes.size(); ++l)
      std::cout << "compressible neo-Hookean sphere: lambda " << stretches[k] << "  h " << sizes[l]
                << "  radius error " << radius_errors[k][l] << "  tension error " << tension_errors[k][l] << "\n";
    const double order = std::log(tension_errors[k][0] / tension_errors[k][2]) / std::log(sizes[0] / sizes[2]);
    std::cout << "compressible neo-Hookean sphere: lambda " << stretches[k] << "  observed order " << order << "\n";
    CAPTURE(stretches[k]);
    CHECK(radius_errors[k][2] < radius_errors[k][1]);
    CHECK(radius_errors[k][1] < radius_errors[k][0]);
    CHECK(tension_errors[k][2] < tension_errors[k][1]);
    CHECK(tension_errors[k][1] < tension_errors[k][0]);
    CHECK(radius_errors[k][2] < 5e-3);
    CHECK(tension_errors[k][2] < 0.02);
    CHECK(order > 1.5);
  }
}
