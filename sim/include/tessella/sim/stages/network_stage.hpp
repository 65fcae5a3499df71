// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// NetworkStage: a cell-level regulatory network (networks/: species per
// cell, reactions, passive transport and PIN efflux across walls) integrated
// by CVODE over each solve interval. The state is on the tissue: the amount
// of each species (cell property <species>_amount, split by measure at
// division, so divisions conserve it) and its concentration (<species>,
// amount / measure after each solve; growth dilutes it). With PIN transport
// the polarity of each cell (sum of PIN times outward wall normal) is the
// Vec3 cell property <species>_polarity. docs/networks.md.

#include <cstdint>
#include <string>
#include <vector>

#include "tessella/networks/network_integrator.hpp"
#include "tessella/networks/network_model.hpp"
#include "tessella/networks/network_system.hpp"
#include "tessella/sim/stages/coupling_stages.hpp"
#include "tessella/sim/stages/stage.hpp"

namespace tessella::sim {

struct NetworkSpec {
  networks::NetworkModel model;  ///< no species: the stage is off
  /// Per species (model order): the initial concentration, an expression
  /// over x, y, z, measure and the parameters, and the amplitude of the
  /// uniform noise added to it (a draw in [0, noise) per cell).
  std::vector<std::string> initial;
  std::vector<double> noise;
  /// Seed of the initial noise (the run's rng_seed in a YAML run).
  std::uint64_t noise_seed = 0;
  networks::IntegratorOptions integrator;
  /// The Newton matrix's Jacobian (networks::JacobianKind).
  networks::JacobianKind jacobian = networks::JacobianKind::Exact;
  std::size_t every = 1;  ///< integrate every `every` steps, over the time since the last solve

  bool enabled() const { return !model.species.empty(); }
};

class NetworkStage final : public Stage {
 public:
  /// Validates the model and the initial expressions (InputError).
  explicit NetworkStage(NetworkSpec spec);
  std::string name() const override { return "network"; }
  /// <species> and <species>_amount of every species.
  std::vector<std::string> cellPropertiesWritten() const override;
  /// Sets the initial concentrations and amounts (kept when the tissue
  /// already has them: a snapshot of the run) and the polarity.
  void prepare(Tissue& tissue, double time) override;
  void apply(Tissue& tissue, const StepContext& context) override;
  std::size_t solves() const { return schedule_.solves(); }
  const networks::IntegratorStatistics& statistics() const { return stats_; }
  const NetworkSpec& spec() const { return spec_; }

 private:
  void writeOutputs(Tissue& tissue, const std::vector<CellId>& cells, networks::NetworkSystem& system,
                    const std::vector<double>& y);

  NetworkSpec spec_;
  SolveSchedule schedule_;
  networks::IntegratorStatistics stats_;
};

}  // namespace tessella::sim
