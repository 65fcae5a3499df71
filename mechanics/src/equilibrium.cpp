// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/equilibrium.hpp"

#include "tessella/mechanics/errors.hpp"
#include "tessella/solvers/errors.hpp"
#include "tessella/tissue/format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace tessella::mechanics {
namespace {

void checkOptions(const EquilibriumOptions& o) {
  auto bad = [](const std::string& name, double value, const char* why) {
    throw InputError("equilibrium option " + name + " = " + formatNumber(value) + ": " + why);
  };
  if (!(o.relative_tolerance >= 0.0)) bad("relative_tolerance", o.relative_tolerance, "must be >= 0");
  if (!(o.absolute_tolerance >= 0.0)) bad("absolute_tolerance", o.absolute_tolerance, "must be >= 0");
  if (!(o.relative_tolerance > 0.0 || o.absolute_tolerance > 0.0))
    bad("relative_tolerance", o.relative_tolerance, "one of the tolerances must be > 0");
  if (o.max_iterations < 1) bad("max_iterations", o.max_iterations, "must be >= 1");
  if (!(o.armijo > 0.0 && o.armijo < 0.5)) bad("armijo", o.armijo, "must be in (0, 0.5)");
  if (!(o.backtrack > 0.0 && o.backtrack < 1.0)) bad("backtrack", o.backtrack, "must be in (0, 1)");
  if (o.max_backtracks < 1) bad("max_backtracks", o.max_backtracks, "must be >= 1");
  if (o.max_shifts < 1) bad("max_shifts", o.max_shifts, "must be >= 1");
}

std::string where(const EquilibriumOptions& o) { return o.context.empty() ? std::string() : " (" + o.context + ")"; }

}  // namespace

EquilibriumReport solveEquilibrium(const EnergyModel& model, Eigen::VectorXd& x, const std::vector<std::uint8_t>& fixed,
                                   const EquilibriumOptions& options) {
  checkOptions(options);
  const Eigen::Index n = model.size();
  if (x.size() != n)
    throw InputError("solveEquilibrium: x has " + std::to_string(x.size()) + " entries, the model " +
                     std::to_string(n));
  if (!fixed.empty() && static_cast<Eigen::Index>(fixed.size()) != n)
    throw InputError("solveEquilibrium: fixed has " + std::to_string(fixed.size()) + " entries, the model " +
                     std::to_string(n));

  // Free degrees of freedom, numbered in order.
  std::vector<Eigen::Index> free_of(static_cast<std::size_t>(n), -1);
  std::vector<Eigen::Index> free_dofs;
  for (Eigen::Index i = 0; i < n; ++i)
    if (fixed.empty() || !fixed[static_cast<std::size_t>(i)]) {
      free_of[static_cast<std::size_t>(i)] = static_cast<Eigen::Index>(free_dofs.size());
      free_dofs.push_back(i);
    }
  const Eigen::Index m = static_cast<Eigen::Index>(free_dofs.size());

  const Eigen::VectorXd x_entry = x;
  EquilibriumReport report;
  Eigen::VectorXd g_full(n), g(m), trial(n);
  auto freeGradient = [&](const Eigen::VectorXd& at) {
    model.gradient(at, g_full);
    for (Eigen::Index k = 0; k < m; ++k) g[k] = g_full[free_dofs[static_cast<std::size_t>(k)]];
  };
  auto fail = [&](const std::string& why) {
    const double residual = report.residual;
    const int iterations = report.iterations;
    x = x_entry;
    std::ostringstream msg;
    msg << "mechanics: equilibrium not reached" << where(options) << ": " << why << " after " << iterations
        << " Newton iterations; residual " << formatNumber(residual, 6) << " (tolerance "
        << formatNumber(report.tolerance, 6) << ", force scale " << formatNumber(report.force_scale, 6)
        << "); positions restored";
    throw EquilibriumError(msg.str(), iterations, residual);
  };

  double energy = model.energy(x);
  freeGradient(x);
  report.energy = energy;
  report.residual = g.norm();
  report.force_scale = model.forceScale(x);
  report.tolerance = options.relative_tolerance * report.force_scale + options.absolute_tolerance;
  report.residuals.push_back(report.residual);
  report.energies.push_back(energy);
  if (!std::isfinite(energy) || !std::isfinite(report.residual)) fail("the energy or its gradient is not finite");

  std::vector<Triplet> entries, reduced;
  solvers::LinearSolver solver(options.linear);
  while (report.residual > report.tolerance) {
    if (report.iterations >= options.max_iterations) fail("no convergence");
    // Tangent on the free dofs.
    entries.clear();
    model.hessian(x, entries);
    reduced.clear();
    reduced.reserve(entries.size());
    for (const Triplet& t : entries) {
      const Eigen::Index r = free_of[static_cast<std::size_t>(t.row())];
      const Eigen::Index c = free_of[static_cast<std::size_t>(t.col())];
      if (r >= 0 && c >= 0) reduced.emplace_back(r, c, t.value());
    }
    solvers::SparseMatrix K(m, m);
    K.setFromTriplets(reduced.begin(), reduced.end());
    double diag_max = 0.0;
    for (Eigen::Index k = 0; k < m; ++k) diag_max = std::max(diag_max, std::abs(K.coeff(k, k)));
    if (!(diag_max > 0.0)) diag_max = 1.0;
    // Positions are known to eps |x|, so forces only to about that times the
    // stiffness: a residual below this floor is round-off (an unloaded body
    // has a force scale near zero, and no Newton step can do better).
    report.roundoff_floor = 16.0 * std::numeric_limits<double>::epsilon() * diag_max *
                            std::max(x.lpNorm<Eigen::Infinity>(), 1e-300) * std::sqrt(static_cast<double>(m));
    report.tolerance = std::max(report.tolerance, report.roundoff_floor);
    if (report.residual <= report.tolerance) break;

    // Newton direction, with a shift when K is not positive definite or the
    // step does not descend.
    Eigen::VectorXd d;
    double tau = 0.0;
    bool found = false;
    for (int attempt = 0; attempt <= options.max_shifts; ++attempt) {
      solvers::SparseMatrix A = K;
      if (tau > 0.0)
        for (Eigen::Index k = 0; k < m; ++k) A.coeffRef(k, k) += tau;
      try {
        solver.compute(A);
        d = solver.solve(-g);
        ++report.linear_solves;
        if (d.allFinite() && g.dot(d) < 0.0) {
          found = true;
          break;
        }
      } catch (const solvers::SolverError&) {
        // not positive definite (or singular): shift
      }
      tau = tau == 0.0 ? 1e-8 * diag_max : 10.0 * tau;
    }
    if (!found) fail("no descent direction even with a shift of " + formatNumber(tau, 3) + " on the tangent");

    // Backtracking line search on E (Armijo). A trial whose energy change is
    // below round-off of the energy's terms cannot be judged by E: it is
    // accepted when it lowers the residual instead.
    const double slope = g.dot(d);
    const double roundoff = 64.0 * std::numeric_limits<double>::epsilon() * model.energyScale(x);
    const double residual_before = report.residual;
    double alpha = 1.0;
    bool accepted = false;
    double trial_energy = energy;
    for (int b = 0; b < options.max_backtracks; ++b) {
      trial = x;
      for (Eigen::Index k = 0; k < m; ++k) trial[free_dofs[static_cast<std::size_t>(k)]] += alpha * d[k];
      trial_energy = model.energy(trial);
      if (std::isfinite(trial_energy)) {
        if (trial_energy <= energy + options.armijo * alpha * slope) {
          accepted = true;
        } else if (std::abs(trial_energy - energy) <= roundoff) {
          freeGradient(trial);
          accepted = g.allFinite() && g.norm() < residual_before;
          freeGradient(x);
        }
      }
      if (accepted) break;
      alpha *= options.backtrack;
    }
    if (!accepted) fail("the line search found no decrease of the energy");
    x = trial;
    energy = trial_energy;
    freeGradient(x);
    ++report.iterations;
    report.energy = energy;
    report.residual = g.norm();
    report.force_scale = model.forceScale(x);
    report.tolerance = std::max(options.relative_tolerance * report.force_scale + options.absolute_tolerance,
                                report.roundoff_floor);
    report.residuals.push_back(report.residual);
    report.energies.push_back(energy);
    report.shifts.push_back(tau);
    report.step_lengths.push_back(alpha);
    if (!std::isfinite(report.residual)) fail("the gradient is not finite");
  }
  return report;
}

}  // namespace tessella::mechanics
