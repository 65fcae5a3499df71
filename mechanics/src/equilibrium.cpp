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

const EnumTable<solvers::SolverMethod>& tangentSolvers() {
  static const EnumTable<solvers::SolverMethod> table(
      "tangent solver",
      {{"auto", solvers::SolverMethod::Auto,
        "CHOLMOD for tangents of 5000 free dofs or more when built with it, else Eigen's simplicial LDL^T (the "
        "default)."},
       {"ldlt", solvers::SolverMethod::Direct, "Eigen's simplicial LDL^T at any size."},
       {"cholmod", solvers::SolverMethod::Cholmod,
        "CHOLMOD's supernodal Cholesky: several times faster on large 3D tissues (builds with CHOLMOD only)."}});
  return table;
}

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
  if (o.auto_cholmod_unknowns < 0)
    bad("auto_cholmod_unknowns", static_cast<double>(o.auto_cholmod_unknowns), "must be >= 0");
}

std::string where(const EquilibriumOptions& o) { return o.context.empty() ? std::string() : " (" + o.context + ")"; }

// The tangent K on the free dofs from the model's Hessian entries. The first
// Hessian builds K's sparsity pattern (setFromTriplets) and the place of each
// of its entries among K's values; a later Hessian with the same entries (rows
// and columns in the same order: a model's pattern is fixed during a solve)
// only scatters its values there, summed in the entries' order from -0 (the
// additive identity) as setFromTriplets sums repeated entries, so K is the
// same bit for bit and the linear solver reuses its symbolic analysis. Any
// other Hessian rebuilds the pattern.
class FreeTangent {
 public:
  using StorageIndex = solvers::SparseMatrix::StorageIndex;

  FreeTangent(const std::vector<Eigen::Index>& free_of, Eigen::Index m) : free_of_(free_of), m_(m) {}

  const solvers::SparseMatrix& assemble(const std::vector<Triplet>& entries) {
    bool same = built_ && entries.size() == place_.size();
    if (same) {
      double* value = K_.valuePtr();
      std::fill(value, value + K_.nonZeros(), -0.0);
      const StorageIndex* outer = K_.outerIndexPtr();
      const StorageIndex* inner = K_.innerIndexPtr();
      for (std::size_t k = 0; k < entries.size() && same; ++k) {
        const Eigen::Index r = free_of_[static_cast<std::size_t>(entries[k].row())];
        const Eigen::Index c = free_of_[static_cast<std::size_t>(entries[k].col())];
        const StorageIndex s = place_[k];
        if (r < 0 || c < 0) {
          same = s < 0;
        } else {
          same = s >= outer[c] && s < outer[c + 1] && inner[s] == r;
          if (same) value[s] += entries[k].value();
        }
      }
    }
    if (!same) rebuild(entries);
    return K_;
  }

  double diagonal(Eigen::Index k) const {
    const StorageIndex s = diagonal_[static_cast<std::size_t>(k)];
    return s < 0 ? 0.0 : K_.valuePtr()[s];
  }

  /// K + tau I: K's pattern when it holds the whole diagonal (the solver then
  /// only refactorises), else with the missing diagonal entries inserted.
  const solvers::SparseMatrix& shifted(double tau) {
    if (!whole_diagonal_) {
      shifted_ = K_;
      for (Eigen::Index k = 0; k < m_; ++k) shifted_.coeffRef(k, k) += tau;
      return shifted_;
    }
    if (shifted_.nonZeros() != K_.nonZeros() || shifted_.rows() != m_) shifted_ = K_;
    std::copy(K_.valuePtr(), K_.valuePtr() + K_.nonZeros(), shifted_.valuePtr());
    for (StorageIndex s : diagonal_) shifted_.valuePtr()[s] += tau;
    return shifted_;
  }

 private:
  void rebuild(const std::vector<Triplet>& entries) {
    std::vector<Triplet> reduced;
    reduced.reserve(entries.size());
    for (const Triplet& t : entries) {
      const Eigen::Index r = free_of_[static_cast<std::size_t>(t.row())];
      const Eigen::Index c = free_of_[static_cast<std::size_t>(t.col())];
      if (r >= 0 && c >= 0) reduced.emplace_back(r, c, t.value());
    }
    K_ = solvers::SparseMatrix(m_, m_);
    K_.setFromTriplets(reduced.begin(), reduced.end());
    const StorageIndex* outer = K_.outerIndexPtr();
    const StorageIndex* inner = K_.innerIndexPtr();
    auto find = [&](Eigen::Index r, Eigen::Index c) -> StorageIndex {
      const StorageIndex* at = std::lower_bound(inner + outer[c], inner + outer[c + 1], static_cast<StorageIndex>(r));
      return at != inner + outer[c + 1] && *at == r ? static_cast<StorageIndex>(at - inner) : -1;
    };
    place_.resize(entries.size());
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const Eigen::Index r = free_of_[static_cast<std::size_t>(entries[k].row())];
      const Eigen::Index c = free_of_[static_cast<std::size_t>(entries[k].col())];
      place_[k] = r >= 0 && c >= 0 ? find(r, c) : -1;
    }
    diagonal_.resize(static_cast<std::size_t>(m_));
    whole_diagonal_ = true;
    for (Eigen::Index k = 0; k < m_; ++k) {
      diagonal_[static_cast<std::size_t>(k)] = find(k, k);
      whole_diagonal_ = whole_diagonal_ && diagonal_[static_cast<std::size_t>(k)] >= 0;
    }
    shifted_ = solvers::SparseMatrix();
    built_ = true;
  }

  const std::vector<Eigen::Index>& free_of_;
  Eigen::Index m_;
  bool built_ = false;
  solvers::SparseMatrix K_, shifted_;
  std::vector<StorageIndex> place_;     // per Hessian entry: its index in K_'s values, -1 off the free dofs
  std::vector<StorageIndex> diagonal_;  // per free dof: the index of K_(k, k), -1 when absent
  bool whole_diagonal_ = true;
};

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

  std::vector<Triplet> entries;
  FreeTangent tangent(free_of, m);
  solvers::LinearSolverOptions linear = options.linear;
  if (linear.method == solvers::SolverMethod::Auto && solvers::solverAvailable(solvers::SolverMethod::Cholmod) &&
      m >= options.auto_cholmod_unknowns)
    linear.method = solvers::SolverMethod::Cholmod;
  solvers::LinearSolver solver(linear);
  while (report.residual > report.tolerance) {
    if (report.iterations >= options.max_iterations) fail("no convergence");
    // Tangent on the free dofs.
    entries.clear();
    model.hessian(x, entries);
    const solvers::SparseMatrix& K = tangent.assemble(entries);
    double diag_max = 0.0;
    for (Eigen::Index k = 0; k < m; ++k) diag_max = std::max(diag_max, std::abs(tangent.diagonal(k)));
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
      try {
        solver.compute(tau > 0.0 ? tangent.shifted(tau) : K);
        d = solver.solve(-g);
        ++report.linear_solves;
        report.linear_method = solver.method();
        report.analyses = solver.analyses();
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
