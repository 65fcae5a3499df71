// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Membrane elements (constant-strain triangles, St Venant-Kirchhoff,
// transversely isotropic) on closed surfaces under pressure: derivatives
// against finite differences, a sphere against the exact SVK membrane
// solution and the membrane stress P r / (2 t), a capped cylinder against the
// hoop P r / t and axial P r / (2 t) stresses, and the errors' decrease
// under refinement.
#include <catch2/catch.hpp>

#include "membrane_derivatives.hpp"
#include "membrane_strains.hpp"
#include "surface_meshes.hpp"
#include "tessella/mechanics/equilibrium.hpp"
#include "tessella/mechanics/membrane_model.hpp"
#include "tessella/tissue/errors.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

using namespace tessella;
using namespace tessella::mechanics;

using test::supports;
using test::inPlane;

namespace {

Eigen::Vector3d centroid(const Eigen::VectorXd& x, const std::array<Index, 3>& t) {
  return (x.segment<3>(3 * t[0]) + x.segment<3>(3 * t[1]) + x.segment<3>(3 * t[2])) / 3.0;
}

double triangleArea(const Eigen::VectorXd& x, const std::array<Index, 3>& t) {
  return 0.5 * (x.segment<3>(3 * t[1]) - x.segment<3>(3 * t[0]))
                   .cross(x.segment<3>(3 * t[2]) - x.segment<3>(3 * t[0]))
                   .norm();
}

const MembraneMaterial kMaterial{.young = 1000.0, .poisson = 0.3, .thickness = 0.01, .fibre_ratio = 1.0};

}  // namespace

TEST_CASE("membrane: gradient and Hessian equal finite differences (anisotropic, deformed, pressurised)",
          "[mechanics][membrane]") {
  const test::SurfaceMesh m = test::capsuleMesh(1.0, 2.0, 2, 3, 6);
  std::vector<Vec3> fibres;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t e = 0; e < m.triangles.size(); ++e) fibres.emplace_back(u(rng), u(rng), u(rng));
  MembraneMaterial material = kMaterial;
  material.fibre_ratio = 10.0;
  const MembraneModel model(m.points, m.triangles, material, 0.7, fibres);
  Eigen::VectorXd x = model.referenceDofs();
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += 0.05 * u(rng);  // strains of a few per cent, both signs
  test::checkMembraneDerivatives(model, x);
  // The enclosed volume: the reference capsule's is close to pi R^2 H + 4/3 pi R^3.
  const double exact = std::numbers::pi * 2.0 + 4.0 / 3.0 * std::numbers::pi;
  CHECK(model.volume(model.referenceDofs()) == Approx(exact).epsilon(0.3));
  CHECK(model.volume(model.referenceDofs()) < exact);  // inscribed polyhedron
}

TEST_CASE("membrane: the material law reduces to isotropic plane stress and refuses bad values",
          "[mechanics][membrane]") {
  const Eigen::Matrix3d q = kMaterial.planeStressMatrix();
  const double E = kMaterial.young, nu = kMaterial.poisson;
  CHECK(q(0, 0) == Approx(E / (1 - nu * nu)));
  CHECK(q(0, 1) == Approx(nu * E / (1 - nu * nu)));
  CHECK(q(2, 2) == Approx(E / (2 * (1 + nu))));
  MembraneMaterial stiff = kMaterial;
  stiff.fibre_ratio = 10.0;
  const Eigen::Matrix3d qs = stiff.planeStressMatrix();
  // Uniaxial stress along the fibres: the compliance gives E1 = 10 E.
  CHECK(1.0 / qs.inverse()(0, 0) == Approx(10 * E));
  CHECK(1.0 / qs.inverse()(1, 1) == Approx(E));
  stiff.poisson = 0.6;
  CHECK_THROWS_WITH(stiff.check(), Catch::Contains("poisson 0.6"));
  const test::SurfaceMesh m = test::sphereMesh(1.0, 3, 6);
  std::vector<std::array<Index, 3>> bad = m.triangles;
  bad[4][2] = 999;
  CHECK_THROWS_WITH(MembraneModel(m.points, bad, kMaterial, 1.0), Catch::Contains("membrane triangle 4"));
}

TEST_CASE("membrane: a pressurised sphere matches the SVK membrane solution; the error falls under refinement",
          "[mechanics][membrane]") {
  // Exact: r = lambda R with t E / (1 - nu) (lambda^2 - 1) = P R lambda, and
  // the membrane tension (force per current length) N = P r / 2 in every
  // direction, i.e. the stress P r / (2 t).
  const double R = 1.0, P = 1.0, E = kMaterial.young, t = kMaterial.thickness, nu = kMaterial.poisson;
  const double beta = P * R * (1 - nu) / (t * E);
  const double lambda = 0.5 * (beta + std::sqrt(beta * beta + 4.0));
  const double N_exact = P * lambda * R / 2;
  std::vector<double> errors, radius_errors, sizes;
  for (int level : {1, 2, 4}) {
    const test::SurfaceMesh m = test::sphereMesh(R, 6 * level - 1, 12 * level);
    const MembraneModel model(m.points, m.triangles, kMaterial, P);
    Eigen::VectorXd x = model.referenceDofs();
    EquilibriumOptions options;
    options.relative_tolerance = 1e-12;
    const EquilibriumReport report = solveEquilibrium(model, x, supports(m), options);
    CHECK(report.shifts.back() == 0.0);
    // Centre: midway between the poles (on the axis by the supports).
    const Eigen::Vector3d centre = 0.5 * (x.segment<3>(0) + x.segment<3>(3));
    double radius_error = 0.0;
    for (std::size_t i = 0; i < m.points.size(); ++i)
      radius_error = std::max(radius_error, std::abs((x.segment<3>(3 * i) - centre).norm() / (lambda * R) - 1));
    // Area-weighted RMS of the relative error of both principal tensions.
    double sum = 0.0, area = 0.0;
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
      const Eigen::Vector2d n = inPlane(model.tension(x, e));
      const double a = triangleArea(x, m.triangles[e]);
      sum += a * ((n[0] - N_exact) * (n[0] - N_exact) + (n[1] - N_exact) * (n[1] - N_exact)) / (N_exact * N_exact);
      area += a;
    }
    errors.push_back(std::sqrt(0.5 * sum / area));
    radius_errors.push_back(radius_error);
    sizes.push_back(2 * std::numbers::pi * R / (12 * level));
  }
  for (std::size_t k = 0; k < errors.size(); ++k)
    std::cout << "membrane sphere: h " << sizes[k] << "  tension RMS error " << errors[k] << "  radius error "
              << radius_errors[k] << "\n";
  const double order = std::log(errors[0] / errors[2]) / std::log(sizes[0] / sizes[2]);
  std::cout << "membrane sphere: observed order of the tension error " << order << "\n";
  CHECK(errors[2] < errors[1]);
  CHECK(errors[1] < errors[0]);
  CHECK(errors[2] < 0.02);
  CHECK(order > 1.5);  // CST stresses on the faceted sphere: second order observed
  CHECK(radius_errors[2] < radius_errors[0]);
  CHECK(radius_errors[2] < 5e-3);
}

TEST_CASE("membrane: a pressurised capped cylinder carries hoop P r / t and axial P r / (2 t)",
          "[mechanics][membrane]") {
  const double R = 1.0, H = 6.0, P = 1.0;
  std::vector<double> hoop_errors, axial_errors, sizes;
  for (int level : {1, 2, 4}) {
    const int around = 12 * level;
    const double h = 2 * std::numbers::pi * R / around;
    const test::SurfaceMesh m = test::capsuleMesh(R, H, 3 * level, static_cast<int>(std::lround(H / h)) + 1, around);
    const MembraneModel model(m.points, m.triangles, kMaterial, P);
    Eigen::VectorXd x = model.referenceDofs();
    EquilibriumOptions options;
    options.relative_tolerance = 1e-12;
    solveEquilibrium(model, x, supports(m), options);
    // The middle third: radius from the points there, stresses of its triangles.
    const double z_mid = 0.5 * (x[2] + x[5]);
    double r = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < m.points.size(); ++i)
      if (std::abs(x[3 * i + 2] - z_mid) < H / 6) r += std::hypot(x[3 * i], x[3 * i + 1]), ++count;
    r /= count;
    double hoop = 0.0, axial = 0.0;
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
      const Eigen::Vector3d c = centroid(x, m.triangles[e]);
      if (std::abs(c.z() - z_mid) >= H / 6) continue;
      const Eigen::Vector3d e_theta = Eigen::Vector3d(-c.y(), c.x(), 0).normalized();
      const Eigen::Matrix3d N = model.tension(x, e);
      hoop = std::max(hoop, std::abs(e_theta.dot(N * e_theta) / (P * r) - 1));
      axial = std::max(axial, std::abs(Eigen::Vector3d::UnitZ().dot(N * Eigen::Vector3d::UnitZ()) / (P * r / 2) - 1));
    }
    hoop_errors.push_back(hoop);
    axial_errors.push_back(axial);
    sizes.push_back(h);
  }
  for (std::size_t k = 0; k < sizes.size(); ++k)
    std::cout << "membrane cylinder: h " << sizes[k] << "  hoop error " << hoop_errors[k] << "  axial error "
              << axial_errors[k] << "\n";
  const double hoop_order = std::log(hoop_errors[0] / hoop_errors[2]) / std::log(sizes[0] / sizes[2]);
  const double axial_order = std::log(axial_errors[0] / axial_errors[2]) / std::log(sizes[0] / sizes[2]);
  std::cout << "membrane cylinder: observed orders hoop " << hoop_order << ", axial " << axial_order << "\n";
  CHECK(hoop_errors[2] < hoop_errors[0]);
  CHECK(axial_errors[2] < axial_errors[0]);
  CHECK(hoop_errors[2] < 0.02);
  CHECK(axial_errors[2] < 0.02);
  CHECK(hoop_order > 1.5);
  CHECK(axial_order > 1.5);
}

TEST_CASE("membrane: stiff hoop fibres (ratio 10) make a pressurised cylinder stretch as the orthotropic law says",
          "[mechanics][membrane]") {
  // The stresses of the cylinder's middle are statically determinate
  // (hoop P r / t, axial P r / (2 t)) whatever the material; the Green strains
  // follow from the compliance Q^-1 in the fibre frame (1: hoop, 2: axial).
  const double R = 1.0, H = 6.0, P = 0.1;
  const int around = 48;
  const test::SurfaceMesh m = test::capsuleMesh(R, H, 12, 45, around);
  std::vector<Vec3> fibres;
  for (const auto& t : m.triangles) {
    const Vec3 c = (m.points[t[0]] + m.points[t[1]] + m.points[t[2]]) / 3.0;
    fibres.emplace_back(-c.y(), c.x(), 0.0);  // hoop (at the poles: any direction, the caps do not matter)
  }
  MembraneMaterial material = kMaterial;
  material.fibre_ratio = 10.0;
  const MembraneModel model(m.points, m.triangles, material, P, fibres);
  Eigen::VectorXd x = model.referenceDofs();
  solveEquilibrium(model, x, supports(m), {});
  const double z_mid = 0.5 * (x[2] + x[5]);
  double hoop_stretch = 0.0, axial_stretch = 0.0;
  int nh = 0, na = 0;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const Vec3& X = m.points[i];
    if (std::abs(X.z()) > H / 6) continue;
    hoop_stretch += std::hypot(x[3 * i], x[3 * i + 1]) / std::hypot(X.x(), X.y()), ++nh;
    if (std::abs(X.z()) > H / 12) axial_stretch += (x[3 * i + 2] - z_mid) / X.z(), ++na;
  }
  hoop_stretch /= nh;
  axial_stretch /= na;
  const double r = hoop_stretch * R;
  const Eigen::Vector3d sigma(P * r / material.thickness, P * r / (2 * material.thickness), 0.0);
  const Eigen::Vector3d predicted = material.planeStressMatrix().inverse() * sigma;
  const double hoop_green = 0.5 * (hoop_stretch * hoop_stretch - 1);
  const double axial_green = 0.5 * (axial_stretch * axial_stretch - 1);
  CAPTURE(hoop_green, predicted[0], axial_green, predicted[1]);
  CHECK(hoop_green == Approx(predicted[0]).epsilon(0.03));
  CHECK(axial_green == Approx(predicted[1]).epsilon(0.03));
  CHECK(axial_green > 4 * hoop_green);  // it elongates mostly axially
}
