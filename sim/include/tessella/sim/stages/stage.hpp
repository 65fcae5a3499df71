// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Stage: one process a Simulation applies at every step (growth, division,
// a solve...). Stages run in the order they were added.
//
// The built-in stages (growth_stages.hpp, coupling_stages.hpp) wrap growth/
// and solvers/; each is built from objects (a velocity field, a rule and a
// threshold, a solver's parameters), by a model in C++ or Python or by the
// YAML sections (makeStages(), sections/simulation_config.hpp).

#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "tessella/io/vtu.hpp"
#include "tessella/io/wall_vtu.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::sim {

struct StepContext {
  std::size_t step = 0;  ///< index of the step being taken (0 for the first)
  /// Index of the step on the run's clock: `step` plus the steps the run took
  /// before the snapshot it restarted from (TimeSpan::origin_steps), so that
  /// every-N schedules keep their phase across a restart. The clock's step m
  /// starts at clock_origin + m * clock_dt.
  std::size_t clock_step = 0;
  double clock_origin = 0.0;
  double clock_dt = 0.0;
  double time = 0.0;     ///< time at the start of the step
  double dt = 0.0;       ///< length of this step (the last one may be shorter)
  /// The simulation's random stream: every random draw of a run comes from
  /// it, so a run is reproducible from its RNG seed.
  std::mt19937_64* rng = nullptr;
  /// Time at the end of the step: exactly the next step's `time` (time + dt
  /// may differ from it in the last bit), so births and restarts agree.
  double end_time = 0.0;
  /// The tissue's geometry, shared by the stages and outputs of the run
  /// (Simulation::geometry()): a stage requires the quantities it reads, so
  /// each is computed once per change of the tissue. Null: the stage keeps its own.
  GeometryCache* geometry = nullptr;
};

class Stage {
 public:
  virtual ~Stage() = default;
  /// Short name for messages ("growth", "division").
  virtual std::string name() const = 0;
  /// Advances the tissue over [context.time, context.time + context.dt].
  /// Throws on failure; the Simulation reports which stage and step failed.
  virtual void apply(Tissue& tissue, const StepContext& context) = 0;
  /// Called once when the stage joins a Simulation, with its tissue at that
  /// time, before any step: a stage with state on the tissue (a solver's
  /// initial field) sets it up here, so the initial snapshot shows it.
  virtual void prepare(Tissue& /*tissue*/, double /*time*/) {}
  /// The double cell properties this stage writes (a solver's cell averages,
  /// amounts, stresses): values other stages may read, such as a division
  /// gate. Marks (source cells) are not values and are not listed.
  virtual std::vector<std::string> cellPropertiesWritten() const { return {}; }

  // --- restarts (a stage with state that is not in the tissue) ---------------
  /// Called when a snapshot of the run is about to be written to
  /// `snapshot_path` (Simulation::writeSnapshot): adds what a restart needs
  /// of this stage to the snapshot's run state (keys "<name>.*"), after
  /// writing anything larger to files beside the snapshot (with `options`).
  /// Default: nothing (the stage's state is the tissue's).
  virtual void saveState(const Tissue& /*tissue*/, const std::string& /*snapshot_path*/,
                         const io::VtuOptions& /*options*/, io::RunState& /*state*/) const {}
  /// A run restarted from a snapshot: called before prepare() with the
  /// snapshot's path and run state, so that prepare() continues what
  /// saveState() saved there instead of starting afresh.
  virtual void continueFrom(const std::string& /*snapshot_path*/, const io::RunState& /*state*/) {}
  /// The tags of the files for looking at that saveState() may write beside a
  /// snapshot, <stem>.<tag>.vtu (io::besideSnapshotPath; the network stage's
  /// "pin", the mechanics stage's "walls"): a run lists each in a series of its
  /// own, <series>.<tag>.pvd (io::SeriesWriter::setBesideSeries).
  virtual std::vector<std::string> besideFileTags() const { return {}; }
  /// Values per live wall (slot order) that the mesh series writes on every
  /// wall facet of each wall (mesh.output: <name>_walls_NNNNNN.vtu): the
  /// mechanics stage's walls-file arrays. Default: none.
  virtual io::WallArrays meshWallArrays(const Tissue& /*tissue*/) const { return {}; }
  /// Values per live cell (slot order, io::cellPropertyArrays) that the mesh
  /// series writes on every element of each cell (mesh.output:
  /// <name>_NNNNNN.vtu): a curved sheet's membrane outputs. Default: none.
  virtual io::WallArrays meshCellArrays(const Tissue& /*tissue*/) const { return {}; }
};

}  // namespace tessella::sim
