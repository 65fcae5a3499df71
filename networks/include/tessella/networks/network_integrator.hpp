// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// NetworkIntegrator: advances a NetworkSystem's amounts in time with SUNDIALS
// CVODE (BDF, Newton iteration) on the whole tissue's system, with the
// analytic sparse Jacobian (NetworkSystem::jacobian) factorised by KLU.

#include <cstddef>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

#include "tessella/networks/network_system.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::networks {

struct IntegratorOptions {
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-9;  ///< on amounts
  long max_steps = 100000;           ///< per call of advance()
  double max_step = 0.0;             ///< largest internal step; 0: no limit
};

/// A CVODE failure: the time reached, CVODE's flag, and the species and cell
/// with the largest weighted local error estimate at the failure.
class NetworkIntegrationError : public Error {
 public:
  NetworkIntegrationError(const std::string& message, double time, int flag, std::string species, std::size_t cell)
      : Error(message), time_(time), flag_(flag), species_(std::move(species)), cell_(cell) {}
  double time() const { return time_; }
  int flag() const { return flag_; }
  const std::string& species() const { return species_; }
  std::size_t cell() const { return cell_; }

 private:
  double time_;
  int flag_;
  std::string species_;
  std::size_t cell_;
};

struct IntegratorStatistics {
  long steps = 0;
  long rhs_evaluations = 0;
  long jacobian_evaluations = 0;
  long nonlinear_iterations = 0;
  long error_test_failures = 0;
};

class NetworkIntegrator {
 public:
  /// Checks the options (InputError naming the option); `system` must
  /// outlive the integrator.
  NetworkIntegrator(NetworkSystem& system, IntegratorOptions options = {});
  ~NetworkIntegrator();
  NetworkIntegrator(const NetworkIntegrator&) = delete;
  NetworkIntegrator& operator=(const NetworkIntegrator&) = delete;

  /// Advances the amounts y (size system.size()) from t0 to t1 > t0 (from a
  /// cold start: the history of a previous call is not reused). Throws
  /// NetworkIntegrationError when CVODE fails; an exception of the right-hand
  /// side (a reaction that is not finite) is rethrown as it was.
  void advance(std::span<double> y, double t0, double t1);
  /// Counters summed over every advance() so far.
  const IntegratorStatistics& statistics() const { return stats_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  NetworkSystem& system_;
  IntegratorOptions options_;
  IntegratorStatistics stats_;
};

}  // namespace tessella::networks
