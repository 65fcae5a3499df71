// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include "network_fixtures.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_integrator.hpp"

using namespace tessella;
using namespace tessella::networks;

namespace {
IntegratorOptions tight() {
  IntegratorOptions o;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-14;
  return o;
}
}  // namespace

TEST_CASE("Two cells with passive exchange follow the closed-form exponential", "[networks]") {
  const double V1 = 2.0, V2 = 0.5, L = 1.5, P = 0.3;
  NetworkSystem system(testing::oneSpecies("a", P), testing::chainGraph({V1, V2}, {L}));
  const double c1 = 3.0, c2 = 1.0;
  const double M = V1 * c1 + V2 * c2;
  const double lambda = P * L * (1 / V1 + 1 / V2);
  NetworkIntegrator integrator(system, tight());
  std::vector<double> y{V1 * c1, V2 * c2};
  double t = 0;
  for (double t1 : {0.1, 0.5, 1.0, 3.0}) {
    integrator.advance(y, t, t1);
    t = t1;
    const double delta = (c1 - c2) * std::exp(-lambda * t);
    const double e1 = (M + V2 * delta) / (V1 + V2);
    const double e2 = e1 - delta;
    CHECK(y[0] / V1 == Approx(e1).epsilon(1e-8));
    CHECK(y[1] / V2 == Approx(e2).epsilon(1e-8));
  }
}

TEST_CASE("A uniform chain of cells follows the cosine modes of the path Laplacian", "[networks]") {
  const std::size_t N = 12;
  const double V = 1.3, L = 0.7, P = 0.9, rate = P * L / V;
  NetworkSystem system(testing::oneSpecies("a", P),
                       testing::chainGraph(std::vector<double>(N, V), std::vector<double>(N - 1, L)));
  std::vector<double> c0(N), y(N);
  for (std::size_t i = 0; i < N; ++i) {
    c0[i] = i < N / 3 ? 5.0 : 1.0 + 0.1 * static_cast<double>(i);
    y[i] = V * c0[i];
  }
  NetworkIntegrator integrator(system, tight());
  const double T = 2.5;
  integrator.advance(y, 0.0, T);
  for (std::size_t i = 0; i < N; ++i) {
    double exact = 0.0;
    for (std::size_t k = 0; k < N; ++k) {
      auto v = [&](std::size_t j) {
        return std::cos(std::numbers::pi * static_cast<double>(k) * (static_cast<double>(j) + 0.5) / N);
      };
      double dot = 0.0, norm = 0.0;
      for (std::size_t j = 0; j < N; ++j) {
        dot += c0[j] * v(j);
        norm += v(j) * v(j);
      }
      const double lambda = 2.0 * (1.0 - std::cos(std::numbers::pi * static_cast<double>(k) / N));
      exact += dot / norm * std::exp(-rate * lambda * T) * v(i);
    }
    CHECK(y[i] / V == Approx(exact).epsilon(1e-8));
  }
}

TEST_CASE("A chain of unequal cells matches the matrix exponential", "[networks]") {
  const std::vector<double> V{1.0, 0.4, 2.2, 0.8, 1.5, 0.3};
  const std::vector<double> L{0.5, 1.2, 0.9, 0.3, 1.1};
  const double P = 1.7;
  NetworkSystem system(testing::oneSpecies("a", P), testing::chainGraph(V, L));
  const auto n = static_cast<Eigen::Index>(V.size());
  // d y / dt = A y with A = B diag(1/V), B the weighted Laplacian (negated).
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    const double w = P * L[static_cast<std::size_t>(k)];
    A(k, k) -= w / V[k];
    A(k, k + 1) += w / V[k + 1];
    A(k + 1, k + 1) -= w / V[k + 1];
    A(k + 1, k) += w / V[k];
  }
  Eigen::VectorXd y0(n);
  y0 << 1.0, 4.0, 0.5, 2.0, 0.0, 3.0;
  const double T = 1.7;
  const Eigen::MatrixXd At = A * T;
  const Eigen::VectorXd exact = At.exp() * y0;
  std::vector<double> y(y0.data(), y0.data() + n);
  NetworkIntegrator integrator(system, tight());
  integrator.advance(y, 0.0, T);
  for (Eigen::Index i = 0; i < n; ++i) CHECK(y[static_cast<std::size_t>(i)] == Approx(exact[i]).epsilon(1e-8));
}

TEST_CASE("Transport conserves the total amount to 1e-12 on a hexagonal tissue", "[networks]") {
  Tissue t = hexagonalGrid(8, 7, 1.0);
  GeometryCache geometry;
  NetworkModel m;
  m.species = {{"a", "", 0.8}, {"b", "", 0.05}};
  m.pin.species = "a";
  m.pin.rate = 2.0;
  m.pin.base = 3.0;
  NetworkSystem system(m, networkGraph(t, geometry, {}));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 2.0);
  std::vector<double> y(system.size());
  for (double& v : y) v = u(rng);
  const double a0 = system.totalAmount(y, 0), b0 = system.totalAmount(y, 1);
  IntegratorOptions o;
  o.relative_tolerance = 1e-6;
  o.absolute_tolerance = 1e-9;
  NetworkIntegrator integrator(system, o);
  integrator.advance(y, 0.0, 10.0);
  CHECK(std::abs(system.totalAmount(y, 0) - a0) <= 1e-12 * a0);
  CHECK(std::abs(system.totalAmount(y, 1) - b0) <= 1e-12 * b0);
  // The integration did move the amounts.
  CHECK(integrator.statistics().steps > 10);
}
