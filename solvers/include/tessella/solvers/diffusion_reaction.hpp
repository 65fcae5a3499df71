// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Diffusion-reaction of one or more species on an FeMesh with P1 elements:
//   du/dt = div(D grad u) - k u + p + s(x, t) + r(u_1..u_S)
// D (diffusivity), k (linear decay) and p (production) are per tissue cell; s
// is an optional smooth source; r an optional nonlinear reaction coupling the
// species at each node. Boundary conditions on chosen wall facets: Dirichlet,
// flux (Neumann) and Robin. Time schemes: implicit Euler and Crank-Nicolson;
// steady state. The linear part is implicit; r is explicit (semi-implicit
// scheme, see docs/solvers.md), so each species solves its own SPD system.

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/solvers/assembly.hpp"
#include "tessella/solvers/linear_solver.hpp"
#include "tessella/tissue/enum_table.hpp"

#include <Eigen/Core>

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace tessella::solvers {

/// A function of position and time (boundary values, sources, initial data).
using SpatialFunction = std::function<double(const Eigen::Vector3d& x, double t)>;

/// u = value (or function(x, t) when set) on all nodes of the facets.
struct DirichletCondition {
  std::vector<int> facets;
  double value = 0.0;
  SpatialFunction function;
};

/// Prescribed influx: D grad u . n = influx (n outward), i.e. the amount
/// entering through the facets per unit area (length in 2D) and time.
/// On interior walls this is a surface source.
struct FluxCondition {
  std::vector<int> facets;
  double influx = 0.0;
  SpatialFunction function;  ///< overrides influx when set
};

/// Exchange with an exterior reservoir: -D grad u . n = transfer * (u - exterior).
struct RobinCondition {
  std::vector<int> facets;
  double transfer = 0.0;  ///< >= 0
  double exterior = 0.0;
};

struct Species {
  std::string name = "u";
  /// Per-cell coefficients, indexed by cell id (element_cell); a vector of size
  /// 1 is uniform. Empty decay/production mean zero.
  Eigen::VectorXd diffusivity = Eigen::VectorXd::Ones(1);
  Eigen::VectorXd decay;
  Eigen::VectorXd production;
  /// Optional extra source s(x, t), interpolated at the nodes.
  SpatialFunction source;
  std::vector<DirichletCondition> dirichlet;
  std::vector<FluxCondition> flux;
  std::vector<RobinCondition> robin;
};

/// Nonlinear reaction at one node: given the values of all species there,
/// write their rates. Called serially, once per node and time step.
using ReactionFunction = std::function<void(std::span<const double> u, std::span<double> rate)>;

enum class TimeScheme { ImplicitEuler, CrankNicolson };
/// "implicit_euler", "crank_nicolson" (also the compartment transport's schemes).
const EnumTable<TimeScheme>& timeSchemes();

struct DiffusionOptions {
  TimeScheme scheme = TimeScheme::ImplicitEuler;
  /// Lumped mass keeps a positive solution positive (M-matrix for acute meshes)
  /// but costs accuracy; consistent mass is the default.
  MassType mass = MassType::Consistent;
  LinearSolverOptions linear;
  /// Steady state with a nonlinear reaction: Picard (fixed-point) iterations.
  int picard_max_iterations = 200;
  double picard_tolerance = 1e-10;  ///< on max |u_new - u_old| / max(1, max |u|)
};

class DiffusionReaction {
 public:
  /// The mesh must outlive the solver. Throws InvalidProblemError on bad input
  /// (negative diffusivity, wrong sizes, bad facet indices, negative transfer).
  DiffusionReaction(const mesh::FeMesh& mesh, std::vector<Species> species, DiffusionOptions options = {});
  ~DiffusionReaction();
  DiffusionReaction(DiffusionReaction&&) noexcept;
  DiffusionReaction& operator=(DiffusionReaction&&) noexcept;

  void setReaction(ReactionFunction reaction);

  int numSpecies() const;
  double time() const { return time_; }
  void setTime(double t) { time_ = t; }

  /// Nodal values, one column per species.
  const Eigen::MatrixXd& state() const { return u_; }
  void setState(const Eigen::MatrixXd& u);
  void setState(int species, const Eigen::VectorXd& u);
  void setState(int species, const SpatialFunction& u0);  ///< interpolates u0(x, time())

  /// One step of length dt with the configured scheme (Dirichlet values at t + dt).
  void step(double dt);
  /// ceil(duration / dt) equal steps covering exactly `duration`.
  void advance(double duration, double dt);
  /// Solves the steady problem at the current time, stores it as the state and returns it.
  /// Throws InvalidProblemError for a singular pure-Neumann problem without reaction.
  const Eigen::MatrixXd& solveSteady();

  /// int u dx of a species (with the mass matrix in use).
  double totalAmount(int species) const;
  /// Report of the last linear solve.
  const SolveReport& lastReport() const { return report_; }

 private:
  struct SpeciesData;
  Eigen::VectorXd rhs(int s, double t) const;
  Eigen::VectorXd dirichletValues(int s, double t) const;
  Eigen::MatrixXd reactionRates(const Eigen::MatrixXd& u) const;
  Eigen::VectorXd solveSpecies(int s, const std::function<SparseMatrix()>& make_lhs, double lhs_key,
                               const Eigen::VectorXd& rhs_full, double t, const Eigen::VectorXd& guess);

  const mesh::FeMesh* mesh_;
  DiffusionOptions options_;
  std::vector<SpeciesData> data_;
  ReactionFunction reaction_;
  Eigen::MatrixXd u_, u_prev_;
  bool have_prev_ = false;
  double time_ = 0.0;
  SparseMatrix mass_;
  SolveReport report_;
};

}  // namespace tessella::solvers
