// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/solvers/diffusion_reaction.hpp"

#include "dof_reduction.hpp"
#include "tessella/solvers/assembly_pattern.hpp"
#include "tessella/solvers/element_geometry.hpp"
#include "tessella/solvers/errors.hpp"
#include "tessella/solvers/facets.hpp"

#include <cmath>
#include <memory>
#include <sstream>

namespace tessella::solvers {

const EnumTable<TimeScheme>& timeSchemes() {
  static const EnumTable<TimeScheme> table(
      "time scheme", {{"implicit_euler", TimeScheme::ImplicitEuler, "Implicit Euler (first order)."},
                      {"crank_nicolson", TimeScheme::CrankNicolson, "Crank-Nicolson (second order)."}});
  return table;
}

// Everything of one species that does not change between time steps, plus the
// factorised system of the last step length (refactorised when dt changes).
struct DiffusionReaction::SpeciesData {
  Species spec;
  SparseMatrix A;              // stiffness(D) + mass(k) + Robin boundary mass
  Eigen::VectorXd load;        // production + constant fluxes + Robin exterior
  std::vector<SparseMatrix> flux_mass;  // facet mass of each function-valued flux
  std::vector<std::vector<int>> dirichlet_nodes;
  std::vector<char> fixed;
  detail::DofReduction reduction;
  bool singular_without_time = false;  // pure Neumann, no decay: A is singular
  // Cached reduced system: lhs_key identifies the left-hand side (dt, or 0 for steady).
  double lhs_key = std::nan("");
  SparseMatrix Afc;
  std::unique_ptr<LinearSolver> solver;
};

DiffusionReaction::~DiffusionReaction() = default;
DiffusionReaction::DiffusionReaction(DiffusionReaction&&) noexcept = default;
DiffusionReaction& DiffusionReaction::operator=(DiffusionReaction&&) noexcept = default;

namespace {

void checkFacetList(const mesh::FeMesh& mesh, const std::vector<int>& facets, const std::string& where) {
  for (int f : facets)
    if (f < 0 || f >= mesh.numWallFacets()) {
      std::ostringstream msg;
      msg << where << ": facet index " << f << " out of range [0, " << mesh.numWallFacets() << ")";
      throw InvalidProblemError(msg.str());
    }
}

Eigen::VectorXd interpolate(const mesh::FeMesh& mesh, const SpatialFunction& f, double t) {
  Eigen::VectorXd v(mesh.numNodes());
  for (int i = 0; i < mesh.numNodes(); ++i) v[i] = f(mesh.nodes.row(i).transpose(), t);
  return v;
}

}  // namespace

DiffusionReaction::DiffusionReaction(const mesh::FeMesh& mesh, std::vector<Species> species, DiffusionOptions options)
    : mesh_(&mesh), options_(options) {
  checkMesh(mesh);
  if (species.empty()) throw InvalidProblemError("DiffusionReaction: no species given");
  const int n = mesh.numNodes();
  // One sparsity pattern for the mass and every species' stiffness and decay
  // mass: built once, each matrix is then a fast re-assembly into it.
  const AssemblyPattern pattern(mesh);
  mass_ = pattern.mass(mesh, options_.mass);
  for (std::size_t s = 0; s < species.size(); ++s) {
    SpeciesData d;
    d.spec = std::move(species[s]);
    const std::string who = "species '" + d.spec.name + "'";
    const Eigen::VectorXd D = cellToElement(mesh, d.spec.diffusivity, who + ": diffusivity", true);
    d.A = pattern.stiffness(mesh, D);
    d.load = Eigen::VectorXd::Zero(n);
    bool has_decay = false;
    if (d.spec.decay.size()) {
      // Negative decay (linear growth) is allowed in time; the solver reports
      // the indefinite system if it makes a step or the steady state ill-posed.
      const Eigen::VectorXd k = cellToElement(mesh, d.spec.decay, who + ": decay");
      has_decay = k.cwiseAbs().maxCoeff() > 0.0;
      if (has_decay) d.A += pattern.mass(mesh, options_.mass, k);
    }
    if (d.spec.production.size()) d.load += assembleLoad(mesh, cellToElement(mesh, d.spec.production, who + ": production"));

    bool has_robin = false;
    for (const RobinCondition& r : d.spec.robin) {
      checkFacetList(mesh, r.facets, who + " Robin condition");
      if (!(r.transfer >= 0.0) || !std::isfinite(r.exterior))
        throw InvalidProblemError(who + ": Robin transfer coefficient must be >= 0 and exterior finite");
      if (r.transfer == 0.0 || r.facets.empty()) continue;
      has_robin = true;
      const Eigen::VectorXd h = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(r.facets.size()), r.transfer);
      d.A += assembleFacetMass(mesh, r.facets, h);
      d.load += assembleFacetLoad(mesh, r.facets, h * r.exterior);
    }
    for (const FluxCondition& q : d.spec.flux) {
      checkFacetList(mesh, q.facets, who + " flux condition");
      if (q.function) {
        d.flux_mass.push_back(assembleFacetMass(mesh, q.facets));
      } else {
        d.load += assembleFacetLoad(mesh, q.facets,
                                    Eigen::VectorXd::Constant(static_cast<Eigen::Index>(q.facets.size()), q.influx));
      }
    }
    d.fixed.assign(static_cast<std::size_t>(n), 0);
    for (const DirichletCondition& c : d.spec.dirichlet) {
      checkFacetList(mesh, c.facets, who + " Dirichlet condition");
      d.dirichlet_nodes.push_back(facetNodes(mesh, c.facets));
      for (int i : d.dirichlet_nodes.back()) d.fixed[static_cast<std::size_t>(i)] = 1;
    }
    d.reduction = detail::DofReduction(d.fixed);
    d.singular_without_time = d.reduction.numFixed() == 0 && !has_robin && !has_decay;
    d.solver = std::make_unique<LinearSolver>(options_.linear);
    data_.push_back(std::move(d));
  }
  u_ = Eigen::MatrixXd::Zero(n, numSpecies());
}

int DiffusionReaction::numSpecies() const { return static_cast<int>(data_.size()); }

void DiffusionReaction::setReaction(ReactionFunction reaction) { reaction_ = std::move(reaction); }

void DiffusionReaction::setState(const Eigen::MatrixXd& u) {
  if (u.rows() != mesh_->numNodes() || u.cols() != numSpecies())
    throw InvalidProblemError("DiffusionReaction::setState: expected numNodes x numSpecies values");
  u_ = u;
  have_prev_ = false;
}

void DiffusionReaction::setState(int species, const Eigen::VectorXd& u) {
  if (species < 0 || species >= numSpecies() || u.size() != mesh_->numNodes())
    throw InvalidProblemError("DiffusionReaction::setState: bad species index or vector size");
  u_.col(species) = u;
  have_prev_ = false;
}

void DiffusionReaction::setState(int species, const SpatialFunction& u0) {
  setState(species, interpolate(*mesh_, u0, time_));
}

Eigen::VectorXd DiffusionReaction::rhs(int s, double t) const {
  const SpeciesData& d = data_[static_cast<std::size_t>(s)];
  Eigen::VectorXd b = d.load;
  if (d.spec.source) b += mass_ * interpolate(*mesh_, d.spec.source, t);
  std::size_t k = 0;
  for (const FluxCondition& q : d.spec.flux)
    if (q.function) b += d.flux_mass[k++] * interpolate(*mesh_, q.function, t);
  return b;
}

Eigen::VectorXd DiffusionReaction::dirichletValues(int s, double t) const {
  const SpeciesData& d = data_[static_cast<std::size_t>(s)];
  Eigen::VectorXd g = Eigen::VectorXd::Zero(mesh_->numNodes());
  // Later conditions win where node sets overlap (e.g. a shared corner).
  for (std::size_t c = 0; c < d.spec.dirichlet.size(); ++c) {
    const DirichletCondition& cond = d.spec.dirichlet[c];
    for (int i : d.dirichlet_nodes[c])
      g[i] = cond.function ? cond.function(mesh_->nodes.row(i).transpose(), t) : cond.value;
  }
  return g;
}

Eigen::MatrixXd DiffusionReaction::reactionRates(const Eigen::MatrixXd& u) const {
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(u.rows(), u.cols());
  if (!reaction_) return r;
  std::vector<double> ui(static_cast<std::size_t>(u.cols())), ri(ui.size());
  for (Eigen::Index i = 0; i < u.rows(); ++i) {
    for (Eigen::Index s = 0; s < u.cols(); ++s) ui[static_cast<std::size_t>(s)] = u(i, s);
    std::fill(ri.begin(), ri.end(), 0.0);
    reaction_(ui, ri);
    for (Eigen::Index s = 0; s < u.cols(); ++s) r(i, s) = ri[static_cast<std::size_t>(s)];
  }
  if (!r.allFinite()) throw SolverError("DiffusionReaction: the reaction function returned a non-finite rate");
  return r;
}

Eigen::VectorXd DiffusionReaction::solveSpecies(int s, const std::function<SparseMatrix()>& make_lhs, double lhs_key,
                                                const Eigen::VectorXd& rhs_full, double t,
                                                const Eigen::VectorXd& guess) {
  SpeciesData& d = data_[static_cast<std::size_t>(s)];
  if (!(d.lhs_key == lhs_key)) {  // the matrix is only built when the key (dt) changes
    SparseMatrix Aff;
    d.reduction.split(make_lhs(), Aff, d.Afc);
    d.lhs_key = std::nan("");  // stays invalid if compute() throws
    try {
      d.solver->compute(Aff);
    } catch (const FactorizationError& e) {
      throw FactorizationError("species '" + d.spec.name + "': " + e.what());
    }
    d.lhs_key = lhs_key;
  }
  const Eigen::VectorXd g = dirichletValues(s, t);
  Eigen::VectorXd b = d.reduction.freePart(rhs_full);
  if (d.reduction.numFixed() > 0) b -= d.Afc * d.reduction.fixedPart(g);
  const Eigen::VectorXd x = d.solver->solve(b, d.reduction.freePart(guess));
  report_ = d.solver->lastReport();
  Eigen::VectorXd u = g;
  d.reduction.scatterFree(x, u);
  return u;
}

void DiffusionReaction::step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InvalidProblemError("DiffusionReaction::step: dt must be > 0");
  const double theta = options_.scheme == TimeScheme::ImplicitEuler ? 1.0 : 0.5;
  // Explicit reaction: at u^n for implicit Euler; extrapolated to t + dt/2
  // (1.5 u^n - 0.5 u^{n-1}) for Crank-Nicolson once a previous state exists.
  Eigen::MatrixXd rates;
  if (reaction_) {
    const bool extrapolate = theta == 0.5 && have_prev_;
    rates = reactionRates(extrapolate ? Eigen::MatrixXd(1.5 * u_ - 0.5 * u_prev_) : u_);
  }
  Eigen::MatrixXd next(u_.rows(), u_.cols());
  for (int s = 0; s < numSpecies(); ++s) {
    const SpeciesData& d = data_[static_cast<std::size_t>(s)];
    Eigen::VectorXd b = mass_ * u_.col(s) / dt + theta * rhs(s, time_ + dt);
    if (theta < 1.0) b += (1.0 - theta) * (rhs(s, time_) - d.A * u_.col(s));
    if (reaction_) b += mass_ * rates.col(s);
    next.col(s) = solveSpecies(s, [&] { return SparseMatrix(mass_ / dt + theta * d.A); }, dt, b, time_ + dt, u_.col(s));
  }
  u_prev_ = u_;
  have_prev_ = true;
  u_ = next;
  time_ += dt;
}

void DiffusionReaction::advance(double duration, double dt) {
  if (!(duration >= 0.0) || !(dt > 0.0)) throw InvalidProblemError("DiffusionReaction::advance: need duration >= 0, dt > 0");
  // (1 - 1e-12): a duration that is a whole number of steps up to round-off takes that many.
  const auto steps = static_cast<long>(std::ceil(duration / dt * (1.0 - 1e-12)));
  if (steps == 0) return;
  const double h = duration / static_cast<double>(steps);
  const double t0 = time_;
  for (long i = 0; i < steps; ++i) step(h);
  time_ = t0 + duration;  // no drift from summing h
}

const Eigen::MatrixXd& DiffusionReaction::solveSteady() {
  for (const SpeciesData& d : data_)
    if (d.singular_without_time)
      throw InvalidProblemError("species '" + d.spec.name +
                                "': steady problem with only flux (Neumann) boundaries and no decay is singular "
                                "(the solution is defined up to a constant); add a Dirichlet or Robin condition or decay");
  Eigen::MatrixXd u = u_;
  const int max_it = reaction_ ? options_.picard_max_iterations : 1;
  for (int it = 0; it < max_it; ++it) {
    const Eigen::MatrixXd rates = reactionRates(u);
    Eigen::MatrixXd next(u.rows(), u.cols());
    for (int s = 0; s < numSpecies(); ++s) {
      Eigen::VectorXd b = rhs(s, time_);
      if (reaction_) b += mass_ * rates.col(s);
      next.col(s) = solveSpecies(s, [&] { return data_[static_cast<std::size_t>(s)].A; }, 0.0, b, time_, u.col(s));
    }
    const double change = (next - u).cwiseAbs().maxCoeff() / std::max(1.0, next.cwiseAbs().maxCoeff());
    u = next;
    if (!reaction_ || change <= options_.picard_tolerance) {
      u_ = u;
      have_prev_ = false;
      return u_;
    }
  }
  std::ostringstream msg;
  msg << "DiffusionReaction::solveSteady: Picard iteration for the nonlinear reaction did not converge in "
      << options_.picard_max_iterations << " iterations";
  throw ConvergenceError(msg.str());
}

double DiffusionReaction::totalAmount(int species) const {
  if (species < 0 || species >= numSpecies()) throw InvalidProblemError("totalAmount: bad species index");
  return (mass_ * u_.col(species)).sum();
}

}  // namespace tessella::solvers
