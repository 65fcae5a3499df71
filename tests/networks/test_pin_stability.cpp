// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Linear stability of the uniform state of up-the-gradient transport on a
// regular hexagonal lattice (docs/networks.md, "Linear stability"): the
// growth rate of a plane-wave perturbation
//   V sigma(q) = -V d - 6 u [D L + alpha - beta (2 - u)],  u = 1 - g(q),
//   g(q) = (1/6) sum over the six neighbours of cos(q . e_n),
// with alpha = T P / 6 and beta = T P c0 ln(b) / 6 (saturation 0), and the
// critical ln(b) where the largest sigma crosses zero. Runs on a periodic
// lattice (a torus: every cell has six neighbours, so the uniform state
// c0 = p / d is an exact steady state) seeded with the fastest-growing
// allowed mode: just below the threshold it decays, just above it grows, at
// the predicted rate. With Smith et al.'s options (PIN P(c) = P0 + P1 c, efflux
// g(c) = c^2 / (1 + s c^2)) the same holds with T P replaced by G'(c0) in alpha
// and T P c0 by G(c0) in beta, G(c) = T P(c) g(c).

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "tessella/networks/network_integrator.hpp"

using namespace tessella;
using namespace tessella::networks;

namespace {

constexpr int N = 24;  // N x N cells on a torus
constexpr double kV = 2.598076211353316, kL = 1.0;  // regular hexagons of circumradius 1
constexpr double kD = 0.05, kT = 1.0, kP = 1.0, kProduction = 0.5, kDecay = 0.05;
constexpr double kC0 = kProduction / kDecay;

int cell(int i, int j) { return ((i + N) % N) * N + (j + N) % N; }

// The triangular lattice of hexagon centres in axial coordinates (i, j):
// neighbours (+-1, 0), (0, +-1), (+1, -1), (-1, +1), wrapped.
NetworkGraph torus() {
  NetworkGraph g;
  g.measure.assign(N * N, kV);
  g.centroid.assign(N * N, Vec3::Zero());
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (auto [di, dj] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{1, -1}}) {
        const int a = cell(i, j), b = cell(i + di, j + dj);
        g.interfaces.push_back({std::min(a, b), std::max(a, b), kL, Vec3::Zero()});
      }
  return g;
}

// Smith et al.'s options in the runs that use them.
constexpr double kP1 = 0.1, kSat = 0.02;

NetworkModel model(double base, bool smith = false) {
  NetworkModel m;
  m.species = {{"auxin", "p - d * auxin", kD}};
  m.parameters = {{"p", kProduction}, {"d", kDecay}};
  m.pin.species = "auxin";
  m.pin.base = base;
  m.pin.rate = kT;
  m.pin.total = kP;
  if (smith) {
    m.pin.total_per_concentration = kP1;
    m.pin.efflux = PinEfflux::Saturating;
    m.pin.efflux_saturation = kSat;
  }
  return m;
}

// G(c0) and G'(c0) (G(c) = T P(c) g(c)), written out.
double G0(bool smith) {
  if (!smith) return kT * kP * kC0;
  return kT * (kP + kP1 * kC0) * kC0 * kC0 / (1 + kSat * kC0 * kC0);
}
double dG0(bool smith) {
  if (!smith) return kT * kP;
  const double d = 1 + kSat * kC0 * kC0;
  return kT * (kP1 * kC0 * kC0 / d + (kP + kP1 * kC0) * 2 * kC0 / (d * d));
}

double g(double t1, double t2) { return (std::cos(t1) + std::cos(t2) + std::cos(t1 - t2)) / 3.0; }

// Growth rate of the mode with lattice-average cosine g, for ln(b) = x.
double sigma(double gq, double x, bool smith = false) {
  const double u = 1.0 - gq;
  const double alpha = dG0(smith) / 6.0, beta = G0(smith) * x / 6.0;
  return (-kV * kDecay - 6.0 * u * (kD * kL + alpha - beta * (2.0 - u))) / kV;
}

// The critical ln(b) of the infinite lattice: 3 (B - A)^2 / B = V d with
// A = D L + T P / 6, B = 2 beta = T P c0 ln(b) / 3 (the larger root).
double criticalLogBase(bool smith = false) {
  const double A = kD * kL + dG0(smith) / 6.0, Vd = kV * kDecay;
  const double B = ((6 * A + Vd) + std::sqrt((6 * A + Vd) * (6 * A + Vd) - 36 * A * A)) / 6.0;
  return 3.0 * B / G0(smith);
}

struct Mode {
  int k1 = 0, k2 = 0;
  double g = 1.0;
};

// The allowed mode of the torus with the largest growth rate at ln(b) = x.
Mode fastestMode(double x, bool smith = false) {
  Mode best;
  double s = -1e300;
  for (int k1 = 0; k1 < N; ++k1)
    for (int k2 = 0; k2 < N; ++k2) {
      if (k1 == 0 && k2 == 0) continue;
      const double gq = g(2 * std::numbers::pi * k1 / N, 2 * std::numbers::pi * k2 / N);
      if (sigma(gq, x, smith) > s) {
        s = sigma(gq, x, smith);
        best = {k1, k2, gq};
      }
    }
  return best;
}

// Measured growth rate of `mode` seeded with relative amplitude eps, over [0, T].
double measuredRate(double x, const Mode& mode, double T, bool smith = false) {
  NetworkSystem system(model(std::exp(x), smith), torus());
  const double eps = 1e-4 * kC0;
  std::vector<double> y(N * N), shape(N * N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      shape[cell(i, j)] = std::cos(2 * std::numbers::pi * (mode.k1 * i + mode.k2 * j) / N);
      y[cell(i, j)] = kV * (kC0 + eps * shape[cell(i, j)]);
    }
  auto amplitude = [&](const std::vector<double>& v) {
    double num = 0, den = 0;
    for (int c = 0; c < N * N; ++c) {
      num += (v[c] / kV - kC0) * shape[c];
      den += shape[c] * shape[c];
    }
    return num / den;
  };
  const double a0 = amplitude(y);
  IntegratorOptions o;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-12;
  NetworkIntegrator integrator(system, o);
  integrator.advance(y, 0.0, T);
  return std::log(amplitude(y) / a0) / T;
}

}  // namespace

TEST_CASE("The uniform state of up-the-gradient transport is a steady state on a torus", "[networks]") {
  NetworkSystem system(model(2.0), torus());
  std::vector<double> y(N * N, kV * kC0), ydot(N * N);
  system.rhs(0.0, y, ydot);
  for (double v : ydot) CHECK(std::abs(v) < 1e-12);
}

TEST_CASE("Up-the-gradient patterns appear above the critical PIN base, at the predicted rate", "[networks]") {
  const double xc = criticalLogBase();
  // The discrete modes of the torus reach the continuum's largest rate to within 1 %.
  const Mode at_c = fastestMode(xc);
  CHECK(std::abs(sigma(at_c.g, xc)) < 0.01 * kDecay);
  for (double factor : {0.95, 1.05}) {
    const double x = factor * xc;
    const Mode mode = fastestMode(x);
    const double predicted = sigma(mode.g, x);
    INFO("ln b = " << x << " (critical " << xc << "), mode (" << mode.k1 << ", " << mode.k2 << "), g = " << mode.g
                   << ", predicted rate " << predicted);
    const double T = 3.0 / std::abs(predicted);
    const double measured = measuredRate(x, mode, T);
    CHECK(measured == Approx(predicted).epsilon(0.01));
    if (factor < 1)
      CHECK(measured < 0);
    else
      CHECK(measured > 0);
  }
}

TEST_CASE("With Smith et al.'s PIN options the threshold and the rate follow G(c0) and G'(c0)", "[networks]") {
  const double xc = criticalLogBase(true);
  // The options move the threshold (G'(c0) / G(c0) is not 1 / c0 here).
  CHECK(std::abs(xc - criticalLogBase(false)) > 0.05 * xc);
  for (double factor : {0.95, 1.05}) {
    const double x = factor * xc;
    const Mode mode = fastestMode(x, true);
    const double predicted = sigma(mode.g, x, true);
    INFO("ln b = " << x << " (critical " << xc << "), g = " << mode.g << ", predicted rate " << predicted);
    const double measured = measuredRate(x, mode, 3.0 / std::abs(predicted), true);
    CHECK(measured == Approx(predicted).epsilon(0.01));
    CHECK((factor < 1 ? measured < 0 : measured > 0));
  }
}

TEST_CASE("From noise, runs just below the threshold stay uniform and just above form peaks", "[networks]") {
  const double xc = criticalLogBase();
  for (double factor : {0.95, 1.05}) {
    NetworkSystem system(model(std::exp(factor * xc)), torus());
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
    std::vector<double> y(N * N);
    double start = 0;
    for (double& v : y) {
      const double dc = noise(rng);
      start = std::max(start, std::abs(dc));
      v = kV * (kC0 + dc);
    }
    IntegratorOptions o;
    o.relative_tolerance = 1e-8;
    o.absolute_tolerance = 1e-10;
    NetworkIntegrator integrator(system, o);
    // Long enough for the fastest mode above the threshold to grow by e^12.
    const double T = 12.0 / sigma(fastestMode(1.05 * xc).g, 1.05 * xc);
    integrator.advance(y, 0.0, T);
    double lo = 1e300, hi = 0;
    for (double v : y) {
      lo = std::min(lo, v / kV);
      hi = std::max(hi, v / kV);
    }
    INFO("factor " << factor << ": auxin from " << lo << " to " << hi << " after t = " << T);
    if (factor < 1) {
      CHECK(hi - kC0 < 1e-3 * start);
      CHECK(kC0 - lo < 1e-3 * start);
    } else {
      CHECK(hi - lo > 0.1 * kC0);
    }
  }
}

namespace {
// |q| of the torus mode (k1, k2) for hexagon centres a = sqrt(3) apart
// (circumradius 1): q . a1 = theta1, q . a2 = theta2 with a1 = a (1, 0),
// a2 = a (1/2, sqrt(3)/2), each theta taken in (-pi, pi].
double waveNumber(int k1, int k2) {
  auto wrap = [](int k) {
    double t = 2 * std::numbers::pi * k / N;
    return t > std::numbers::pi ? t - 2 * std::numbers::pi : t;
  };
  const double a = std::sqrt(3.0), t1 = wrap(k1), t2 = wrap(k2);
  const double qx = t1 / a, qy = (t2 - t1 / 2) / (a * std::sqrt(3.0) / 2);
  return std::hypot(qx, qy);
}
}  // namespace

TEST_CASE("Just above the threshold, the pattern's wavelength is that of the fastest-growing mode", "[networks]") {
  const double x = 1.05 * criticalLogBase();
  NetworkSystem system(model(std::exp(x)), torus());
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> noise(-1e-7 * kC0, 1e-7 * kC0);
  std::vector<double> y(N * N);
  for (double& v : y) v = kV * (kC0 + noise(rng));
  IntegratorOptions o;
  o.relative_tolerance = 1e-12;
  o.absolute_tolerance = 1e-14;
  const Mode fastest = fastestMode(x);
  const double rate = sigma(fastest.g, x);
  // Growth by e^10: still linear (amplitude ~ 1e-3 c0), the spectrum gathered near the fastest modes.
  NetworkIntegrator(system, o).advance(y, 0.0, 10.0 / rate);
  // Power spectrum of the deviation; its power-weighted mean wave number.
  double weighted = 0, total = 0, largest = 0;
  for (int k1 = 0; k1 < N; ++k1)
    for (int k2 = 0; k2 < N; ++k2) {
      if (k1 == 0 && k2 == 0) continue;
      double re = 0, im = 0;
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
          const double phase = 2 * std::numbers::pi * (k1 * i + k2 * j) / N;
          const double d = y[cell(i, j)] / kV - kC0;
          re += d * std::cos(phase);
          im -= d * std::sin(phase);
        }
      const double power = re * re + im * im;
      weighted += power * waveNumber(k1, k2);
      total += power;
      largest = std::max(largest, std::sqrt(power) * 2 / (N * N));
    }
  const double measured = 2 * std::numbers::pi / (weighted / total);
  const double predicted = 2 * std::numbers::pi / waveNumber(fastest.k1, fastest.k2);
  INFO("wavelength " << measured << ", fastest-growing mode " << predicted << ", largest mode amplitude "
                     << largest);
  CHECK(largest < 1e-2 * kC0);  // still linear
  CHECK(measured == Approx(predicted).epsilon(0.15));
}
