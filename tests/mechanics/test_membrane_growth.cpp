// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Strain-based growth of membrane rest shapes: a pressurised sphere grows
// isotropically at the rate the growth law predicts (against an independent
// RK4 integration of the sphere's scalar growth ODE), and a pressurised
// cylinder grows around and along at the ratio of its strains: 2 for an
// isotropic wall with nu = 0 (hoop stress twice the axial), 0.2 with hoop
// fibres ten times stiffer.
#include <catch2/catch.hpp>

#include "surface_meshes.hpp"
#include "tessella/mechanics/equilibrium.hpp"
#include "tessella/mechanics/membrane_model.hpp"

#include <cmath>
#include <iostream>
#include <numbers>

using namespace tessella;
using namespace tessella::mechanics;

using test::supports;

TEST_CASE("membrane growth: a pressurised sphere grows isotropically at the rate of its growth ODE",
          "[mechanics][membrane]") {
  const MembraneMaterial material{.young = 1000.0, .poisson = 0.3, .thickness = 0.01, .fibre_ratio = 1.0};
  const double P = 2.0, phi = 1.0, eps_y = 0.01, T = 3.0;
  const int steps = 60;
  // The exact sphere: a rest radius Rr is inflated to lambda Rr with
  // t E (lambda^2 - 1) / (1 - nu) = P Rr lambda; its rest radius grows as
  // dRr/dt = phi Rr max(lambda - 1 - eps_y, 0).
  auto lambda = [&](double Rr) {
    const double beta = P * Rr * (1 - material.poisson) / (material.thickness * material.young);
    return 0.5 * (beta + std::sqrt(beta * beta + 4));
  };
  auto rate = [&](double Rr) { return phi * Rr * std::max(lambda(Rr) - 1 - eps_y, 0.0); };
  double Rr = 1.0;
  const int rk_steps = 4000;
  const double h = T / rk_steps;
  for (int k = 0; k < rk_steps; ++k) {
    const double k1 = rate(Rr), k2 = rate(Rr + 0.5 * h * k1), k3 = rate(Rr + 0.5 * h * k2), k4 = rate(Rr + h * k3);
    Rr += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  const double ode_growth = lambda(Rr) * Rr / lambda(1.0) - 1;  // r(T) / r(0) - 1

  const test::SurfaceMesh m = test::sphereMesh(1.0, 11, 24);
  MembraneModel model(m.points, m.triangles, material, P);
  Eigen::VectorXd x = model.referenceDofs();
  const auto fixed = supports(m);
  auto radii = [&](double& mean, double& spread) {
    const Eigen::Vector3d centre = 0.5 * (x.segment<3>(0) + x.segment<3>(3));
    double lo = 1e300, hi = 0, sum = 0;
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      const double r = (x.segment<3>(3 * i) - centre).norm();
      lo = std::min(lo, r), hi = std::max(hi, r), sum += r;
    }
    mean = sum / m.points.size();
    spread = (hi - lo) / mean;
  };
  solveEquilibrium(model, x, fixed, {});
  double r0 = 0, spread0 = 0;
  radii(r0, spread0);
  const StrainGrowthLaw law{phi, eps_y};
  for (int k = 0; k < steps; ++k) {
    model.growRestShape(x, law, T / steps);
    solveEquilibrium(model, x, fixed, {});
  }
  double r1 = 0, spread1 = 0;
  radii(r1, spread1);
  const double fe_growth = r1 / r0 - 1;
  std::cout << "membrane sphere growth: FE " << fe_growth << ", ODE " << ode_growth << "\n";
  REQUIRE(ode_growth > 0.2);
  CHECK(fe_growth == Approx(ode_growth).epsilon(0.05));
  CHECK(spread1 < 1.5 * spread0);  // it stays about as round as the mesh was: isotropic growth
}

TEST_CASE("membrane growth: a pressurised cylinder grows around and along at the ratio of its strains",
          "[mechanics][membrane]") {
  // nu = 0: hoop strain P r / (t E_hoop), axial P r / (2 t E): their ratio is
  // 2 for an isotropic wall and 2 / 10 with hoop fibres ten times stiffer.
  // The growth of one step is measured on the rest shape itself: the
  // cylinder's middle unloaded (P = 0) after growing.
  for (double ratio : {1.0, 10.0}) {
    CAPTURE(ratio);
    const MembraneMaterial material{.young = 1000.0, .poisson = 0.0, .thickness = 0.01, .fibre_ratio = ratio};
    const double R = 1.0, H = 6.0, P = 0.1, dt = 1.0;
    const test::SurfaceMesh m = test::capsuleMesh(R, H, 8, 31, 32);
    std::vector<Vec3> fibres;
    for (const auto& t : m.triangles) {
      const Vec3 c = (m.points[t[0]] + m.points[t[1]] + m.points[t[2]]) / 3.0;
      fibres.emplace_back(-c.y(), c.x(), 0.0);
    }
    MembraneModel model(m.points, m.triangles, material, P, fibres);
    Eigen::VectorXd x = model.referenceDofs();
    const auto fixed = supports(m);
    solveEquilibrium(model, x, fixed, {});
    model.growRestShape(x, StrainGrowthLaw{1.0, 0.0}, dt);
    model.setPressure(0.0);
    solveEquilibrium(model, x, fixed, {});
    // Hoop and axial growth of the middle third's rest shape.
    const double z_mid = 0.5 * (x[2] + x[5]);
    double hoop = 0, axial = 0;
    int nh = 0, na = 0;
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      const Vec3& X = m.points[i];
      if (std::abs(X.z()) > H / 6) continue;
      hoop += std::log(std::hypot(x[3 * i], x[3 * i + 1]) / std::hypot(X.x(), X.y())), ++nh;
      if (std::abs(X.z()) > H / 12) axial += std::log((x[3 * i + 2] - z_mid) / X.z()), ++na;
    }
    const double hoop_rate = hoop / nh / dt, axial_rate = axial / na / dt;
    const double predicted = 2.0 / ratio;
    std::cout << "membrane cylinder growth (fibre ratio " << ratio << "): hoop rate " << hoop_rate << ", axial rate "
              << axial_rate << ", ratio " << hoop_rate / axial_rate << " (predicted " << predicted << ")\n";
    CHECK(axial_rate > 0.0);
    CHECK(hoop_rate / axial_rate == Approx(predicted).epsilon(0.05));
    // And the axial rate is the law's: phi times the axial strain P r / (2 t E).
    CHECK(axial_rate == Approx(P * R / (2 * material.thickness * material.young)).epsilon(0.05));
  }
}
