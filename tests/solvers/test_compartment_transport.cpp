// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Compartment transport: exact discrete and analytic solutions of small
// networks, exact conservation of the total amount, input validation.
#include <catch2/catch.hpp>

#include "tessella/solvers/compartment_transport.hpp"
#include "tessella/solvers/errors.hpp"

#include <cmath>

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::solvers;

namespace {

CompartmentNetwork twoCells(double v0, double v1, double area, double perm, double polar01 = 0.0) {
  CompartmentNetwork net;
  net.volume = Eigen::Vector2d(v0, v1);
  net.walls.push_back({0, 1, area, perm, polar01, 0.0});
  return net;
}

}  // namespace

TEST_CASE("Two-cell exchange: exact discrete and analytic solutions, total conserved", "[solvers][compartment]") {
  const double V0 = 2.0, V1 = 0.5, A = 0.8, P = 1.25;
  const double lambda = P * A * (1 / V0 + 1 / V1);  // the difference c0 - c1 decays at this rate
  const Eigen::Vector2d c_init(3.0, 1.0);
  const double mean = (V0 * c_init[0] + V1 * c_init[1]) / (V0 + V1);
  const double T = 1.0;
  for (TimeScheme scheme : {TimeScheme::ImplicitEuler, TimeScheme::CrankNicolson}) {
    std::vector<double> err;
    for (int steps : {20, 40, 80}) {
      CompartmentTransport ct(twoCells(V0, V1, A, P), scheme);
      Eigen::VectorXd c = c_init;
      const double total0 = ct.totalAmount(c);
      const double dt = T / steps;
      ct.advance(c, T, dt);
      CHECK(ct.totalAmount(c) == Approx(total0).epsilon(1e-14));
      // Amplification factor of the scheme for the decaying mode.
      const double g = scheme == TimeScheme::ImplicitEuler ? 1 / (1 + lambda * dt)
                                                           : (1 - lambda * dt / 2) / (1 + lambda * dt / 2);
      const double d_discrete = (c_init[0] - c_init[1]) * std::pow(g, steps);
      CHECK(c[0] - c[1] == Approx(d_discrete).epsilon(1e-12));
      const double d_exact = (c_init[0] - c_init[1]) * std::exp(-lambda * T);
      err.push_back(std::abs((c[0] - c[1]) - d_exact));
      // Each concentration: mean +- its share of the difference.
      CHECK(c[0] == Approx(mean + V1 / (V0 + V1) * (c[0] - c[1])).epsilon(1e-13));
    }
    const double expected = scheme == TimeScheme::ImplicitEuler ? 1.0 : 2.0;
    CHECK(std::log2(err[1] / err[2]) == Approx(expected).margin(0.1));
  }
}

TEST_CASE("Polar transport empties the donor exponentially into the acceptor", "[solvers][compartment]") {
  const double V0 = 1.5, V1 = 1.0, A = 0.5, T_rate = 2.0;
  CompartmentTransport ct(twoCells(V0, V1, A, 0.0, T_rate), TimeScheme::CrankNicolson);
  Eigen::VectorXd c = Eigen::Vector2d(1.0, 0.0);
  const double dt = 0.001, T = 1.0;
  ct.advance(c, T, dt);
  const double rate = T_rate * A / V0;
  const double g = (1 - rate * dt / 2) / (1 + rate * dt / 2);
  CHECK(c[0] == Approx(std::pow(g, 1000)).epsilon(1e-12));
  CHECK(c[0] == Approx(std::exp(-rate * T)).epsilon(1e-6));
  CHECK(V1 * c[1] == Approx(V0 * (1.0 - c[0])).epsilon(1e-13));
  // Rate function agrees with the model.
  const Eigen::VectorXd r = ct.rate(Eigen::Vector2d(1.0, 0.0));
  CHECK(r[0] == Approx(-rate));
  CHECK(r[1] == Approx(T_rate * A / V1));
}

TEST_CASE("A random ring network with polar transport conserves its total exactly", "[solvers][compartment]") {
  const int n = 60;
  CompartmentNetwork net;
  net.volume.resize(n);
  unsigned state = 7;
  auto uniform = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  };
  for (int i = 0; i < n; ++i) net.volume[i] = 0.5 + uniform();
  for (int i = 0; i < n; ++i) {
    net.walls.push_back({i, (i + 1) % n, 0.2 + uniform(), uniform(), 3 * uniform(), 0.5 * uniform()});
    if (i % 7 == 0) net.walls.push_back({i, (i + n / 2) % n, 0.1, 2.0, 0.0, 1.0});  // chords
  }
  for (TimeScheme scheme : {TimeScheme::ImplicitEuler, TimeScheme::CrankNicolson}) {
    CompartmentTransport ct(net, scheme);
    Eigen::VectorXd c(n);
    for (int i = 0; i < n; ++i) c[i] = uniform() * 10;
    const double total0 = ct.totalAmount(c);
    const Eigen::VectorXd c0 = c;
    for (int k = 0; k < 200; ++k) ct.step(c, k < 100 ? 0.05 : 0.02);  // dt change refactorises
    CHECK(std::abs(ct.totalAmount(c) - total0) <= 1e-13 * total0);
    CHECK((c - c0).norm() > 1.0);
    CHECK(std::abs(ct.rate(c).dot(net.volume)) <= 1e-12 * c.norm());
  }
}

TEST_CASE("Decay and production drive every cell to p / k", "[solvers][compartment]") {
  CompartmentNetwork net = twoCells(1.0, 2.0, 1.0, 0.3);
  net.decay = Eigen::Vector2d(0.5, 0.5);
  net.production = Eigen::Vector2d(1.0, 1.0);
  CompartmentTransport ct(net);
  Eigen::VectorXd c = Eigen::Vector2d(0.0, 5.0);
  ct.advance(c, 80.0, 0.5);
  CHECK(c[0] == Approx(2.0).epsilon(1e-10));
  CHECK(c[1] == Approx(2.0).epsilon(1e-10));
}

TEST_CASE("Compartment networks are validated", "[solvers][compartment][errors]") {
  CHECK_THROWS_AS(CompartmentTransport(twoCells(0.0, 1.0, 1.0, 1.0)), InvalidProblemError);
  CHECK_THROWS_AS(CompartmentTransport(twoCells(1.0, 1.0, 1.0, -1.0)), InvalidProblemError);
  CHECK_THROWS_AS(CompartmentTransport(twoCells(1.0, 1.0, -0.1, 1.0)), InvalidProblemError);
  CHECK_THROWS_AS(CompartmentTransport(twoCells(1.0, 1.0, 1.0, 1.0, -2.0)), InvalidProblemError);
  CompartmentNetwork self = twoCells(1.0, 1.0, 1.0, 1.0);
  self.walls[0].cell_j = 0;
  CHECK_THROWS_AS(CompartmentTransport(self), InvalidProblemError);
  CompartmentNetwork out = twoCells(1.0, 1.0, 1.0, 1.0);
  out.walls[0].cell_j = 2;
  CHECK_THROWS_AS(CompartmentTransport(out), InvalidProblemError);
  CompartmentTransport ok(twoCells(1.0, 1.0, 1.0, 1.0));
  Eigen::VectorXd wrong = Eigen::VectorXd::Zero(3);
  CHECK_THROWS_AS(ok.step(wrong, 0.1), InvalidProblemError);
}
