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
#include "tessella/tissue/enum_table.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::networks {

/// The linear solver of CVODE's Newton iteration: `Klu`, a sparse LU
/// factorisation of I - gamma J (exact solves, a cost that grows faster than
/// the number of cells); `Gmres`, SPGMR with the products J v from the
/// Jacobian of the last setup and a block-Jacobi preconditioner (per cell,
/// the inverse of the species block of I - gamma J).
enum class LinearSolver { Klu, Gmres };
/// "klu", "gmres".
const EnumTable<LinearSolver>& linearSolvers();

struct IntegratorOptions {
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-9;  ///< on amounts
  long max_steps = 100000;           ///< per call of advance()
  double max_step = 0.0;             ///< largest internal step; 0: no limit
  /// CVODE's linear solver setups (a new Newton matrix I - gamma J and its KLU
  /// factorisation) happen at most every this many steps (CVodeSetLSetupFrequency);
  /// 0: CVODE's default (20).
  long setup_frequency = 0;
  /// A new Jacobian at most every this many steps (CVodeSetJacEvalFrequency);
  /// 0: CVODE's default (51).
  long jacobian_frequency = 0;
  LinearSolver linear_solver = LinearSolver::Klu;
  /// Time the right-hand side, Jacobian and linear solver callbacks (statistics' seconds).
  bool timers = false;
  /// OpenMP threads for the right-hand side, the Jacobian, the preconditioner and (from 131072 unknowns)
  /// the vector operations; 0: OpenMP's default. The results are bit-identical for any number. 1 by
  /// default: the work between two of CVODE's serial steps is short (a millisecond at 10^4 cells), so
  /// threads that wait for each other cost more than they save on a loaded machine.
  int threads = 1;
  /// With threads != 1: let OpenMP run fewer threads than `threads` on a loaded machine
  /// (omp_set_dynamic for the duration of advance(): libgomp then takes the load average off the
  /// number of cores), so that threads do not wait for cores other processes hold. The results do not
  /// change (they are the same for any number of threads).
  bool adapt_threads = true;
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
  long linear_setups = 0;  ///< Newton matrix factorisations (CVodeGetNumLinSolvSetups)
  long linear_solves = 0;  ///< linear solves (counted with IntegratorOptions::timers)
  long linear_iterations = 0;  ///< GMRES iterations (CVodeGetNumLinIters; 0 with KLU)
  /// With IntegratorOptions::timers: wall-clock seconds in the right-hand side, the Jacobian
  /// (evaluation and copy into SUNDIALS' matrix), the linear solver's setups (KLU
  /// (re)factorisation, or the preconditioner's blocks) and its solves.
  double rhs_seconds = 0, jacobian_seconds = 0, setup_seconds = 0, solve_seconds = 0;
  /// Adds `other`'s counters and seconds.
  IntegratorStatistics& operator+=(const IntegratorStatistics& other);
};

class NetworkIntegrator {
 public:
  /// Checks the options (InputError naming the option); `system` must
  /// outlive the integrator. The integrator may be advanced again after
  /// system.updateGraph() (the same structure).
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
  /// Sets the counters to zero.
  void resetStatistics() { stats_ = {}; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  NetworkSystem& system_;
  IntegratorOptions options_;
  IntegratorStatistics stats_;
};

}  // namespace tessella::networks
