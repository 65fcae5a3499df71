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
// Vec3 cell property <species>_polarity. With a dynamic PIN model
// (with_the_flux, expression) the PIN densities are the double wall
// properties <species>_pin_pos and <species>_pin_neg (the density on the
// wall's positive and negative side, networks::onPositiveSide; copied when a
// wall is split, so a density is kept; a new wall starts at pin.initial), and
// the snapshot's run state carries them (network.pin) for restarts. With primordium detection
// (NetworkSpec::primordia) each new primordium's cell gets its id in the int
// cell property `primordium` (0: none; copied to daughters) and a record
// (time, lineage id, position, angle, radius, divergence) that the snapshot's
// run state carries across restarts. docs/networks.md.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessella/networks/network_graph.hpp"
#include "tessella/networks/network_integrator.hpp"
#include "tessella/networks/network_model.hpp"
#include "tessella/networks/network_system.hpp"
#include "tessella/networks/primordia.hpp"
#include "tessella/sim/stages/coupling_stages.hpp"
#include "tessella/sim/stages/stage.hpp"

namespace tessella::sim {

/// Primordium detection after each solve (networks/primordia.hpp).
struct PrimordiaSpec {
  std::string species;  ///< empty: off
  networks::PrimordiumOptions options;
  bool enabled() const { return !species.empty(); }
};

/// One primordium as it started.
struct PrimordiumRecord {
  int id = 0;                 ///< 1, 2, ... in order of appearance (the cell property's value)
  double time = 0.0;          ///< end of the solve that found it
  std::int64_t lineage = 0;   ///< the cell's lineage id
  Vec3 position = Vec3::Zero();  ///< the cell's centroid
  double angle_deg = 0.0;     ///< about the dome's axis, [0, 360)
  double radius = 0.0;        ///< distance from the axis
  double distance = 0.0;      ///< straight-line distance from the apex
  double divergence_deg = 0.0;  ///< from the previous primordium, [0, 360); NaN for the first
};

/// The cell property holding each cell's primordium id.
inline constexpr const char* kPrimordiumProperty = "primordium";

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
  PrimordiaSpec primordia;
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
  /// The primordia found so far, in order of appearance.
  const std::vector<PrimordiumRecord>& primordia() const { return primordia_; }
  /// With PIN transport, writes the PIN density on both sides of every wall
  /// beside the snapshot, <stem>.pin.vtu (docs/output.md). The primordia
  /// records under "network.primordia" and, with a dynamic PIN model, the PIN
  /// densities under "network.pin" (exact numbers; per live wall in slot
  /// order, the density on the side of the cell with the smaller lineage id,
  /// or a boundary wall's cell, then on the other side).
  void saveState(const Tissue& tissue, const std::string& snapshot_path, const io::VtuOptions& options,
                 io::RunState& state) const override;
  /// Restores the records (InputError naming the key and the value when damaged)
  /// and keeps the PIN densities for prepare().
  void continueFrom(const std::string& snapshot_path, const io::RunState& state) override;
  /// "pin" with PIN transport: its walls files are listed in <series>.pin.pvd.
  std::vector<std::string> besideFileTags() const override {
    return spec_.model.pin.enabled() ? std::vector<std::string>{"pin"} : std::vector<std::string>{};
  }
  /// The wall properties holding the PIN density on each side of the walls.
  static std::string pinWallProperty(const std::string& species, bool positive_side);

 private:
  void writeOutputs(Tissue& tissue, const std::vector<CellId>& cells,
                    const std::vector<std::vector<networks::InterfaceWall>>& walls, networks::NetworkSystem& system,
                    const std::vector<double>& y, bool write_pin);
  // The state: amounts from the cells, PIN densities (dynamic models) from the walls' properties.
  std::vector<double> readState(const Tissue& tissue, const std::vector<CellId>& cells,
                                const std::vector<std::vector<networks::InterfaceWall>>& walls,
                                const networks::NetworkSystem& system, const std::vector<double>& amounts) const;
  // The PIN per wall side beside a snapshot: <stem>.pin.vtu (io::writeWallsVtu).
  void writePinWalls(const Tissue& tissue, const std::string& snapshot_path, const io::VtuOptions& options) const;
  void restorePin(Tissue& tissue);
  void detectPrimordia(Tissue& tissue, const std::vector<CellId>& cells, const networks::NetworkSystem& system,
                       const std::vector<double>& y, double time);

  NetworkSpec spec_;
  SolveSchedule schedule_;
  networks::IntegratorStatistics stats_;
  std::vector<PrimordiumRecord> primordia_;
  std::optional<std::pair<std::string, std::string>> restart_pin_;  // snapshot path, its network.pin text
  // The last solve's system and integrator (apply): kept while the tissue's graph keeps its structure.
  std::unique_ptr<networks::NetworkSystem> system_;
  std::unique_ptr<networks::NetworkIntegrator> integrator_;
};

}  // namespace tessella::sim
