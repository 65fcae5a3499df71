// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// PreparedRun: everything `tessella run` does, minus printing, split in two
// so that no file is written until every check has passed:
//
//   prepare()  validates the config, resolves and checks the output
//              directory, builds the tissue (throws ConfigError; writes nothing)
//   execute()  creates the directory, writes run.yaml, then the series and
//              stats.csv (statistics_output.hpp) while the simulation runs
//
// The output directory is, in order: RunOptions::output_directory (--out),
// output.directory, runs/<config name> (relative to the working directory).
// An output_directory that is given but empty (--out '') is refused, not
// taken for "not given".
// A directory that already holds a run (run.yaml or the series' .pvd) is
// refused unless `overwrite` is set, so a re-run never silently replaces results.

#include <memory>
#include <optional>
#include <string>

#include "tessella/sim/run/field_output.hpp"
#include "tessella/sim/run/mesh_output.hpp"
#include "tessella/sim/run/series_output.hpp"
#include "tessella/sim/run/statistics_output.hpp"
#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/sim/simulation.hpp"

namespace tessella::sim {

struct RunOptions {
  std::optional<std::string> output_directory;  ///< overrides output.directory when given; must not be empty
  bool overwrite = false;        ///< replace a run already in the directory
};

class PreparedRun {
 public:
  static PreparedRun prepare(SimulationConfig config, const RunOptions& options = {});
  /// An interrupted run, to be continued in place (`tessella run --resume`):
  /// reads RUN_DIR/run.yaml and restarts from the last complete snapshot of
  /// its series (one that reads back, with its run state and, when the run
  /// has a stats.csv, its row there). execute() then deletes what the
  /// interrupted run wrote after that snapshot (later series entries and
  /// their files, later stats.csv rows, leftover temporaries) and runs to the
  /// end, appending, so that the directory ends as the uninterrupted run's.
  /// Throws InputError naming the directory when it is not a run, has no
  /// complete snapshot, or is already finished; writes nothing.
  static PreparedRun resume(const std::string& run_directory);

  const std::string& outputDirectory() const { return directory_; }
  const SimulationConfig& config() const { return config_; }
  Simulation& simulation() { return simulation_; }
  const Simulation& simulation() const { return simulation_; }

  /// Creates the directory, removes a previous run's files when overwriting,
  /// writes run.yaml and runs to the end, writing the series. Callbacks
  /// registered on simulation() before (e.g. progress) keep running.
  /// A stop flag set on simulation() (Simulation::setStopFlag) ends the run
  /// early between two steps, with every file written so far complete; if it
  /// is set before execute(), nothing is written. interrupted() tells.
  void execute();
  /// execute() returned before the end of the time span, or wrote nothing (stop flag).
  bool interrupted() const { return simulation_.stopRequested() && (!output_ || !simulation_.finished()); }
  /// The series' .pvd (empty before execute()).
  std::string seriesPath() const { return output_ ? output_->pvdPath() : std::string(); }
  /// Snapshots written by execute().
  std::size_t snapshots() const { return output_ ? output_->snapshots() : 0; }
  /// Mesh snapshots written (mesh.output), and how many times the tissue was meshed for them.
  std::size_t meshSnapshots() const { return mesh_output_ ? mesh_output_->snapshots() : 0; }
  std::size_t meshesBuilt() const { return mesh_output_ ? mesh_output_->meshes() : 0; }
  std::string runRecordPath() const;
  /// The snapshot a resumed run continues from (resume()), else empty.
  const std::string& resumedFrom() const { return resumed_from_; }

 private:
  PreparedRun(SimulationConfig config, Simulation simulation, std::string directory, bool overwrite);

  SimulationConfig config_;
  Simulation simulation_;
  std::string directory_;
  bool overwrite_;
  std::optional<double> resume_after_;  // resume(): the time of the snapshot continued from
  std::string resumed_from_;
  std::shared_ptr<SeriesOutput> output_;
  std::shared_ptr<MeshOutput> mesh_output_;  // null unless mesh.output
  std::shared_ptr<FieldSeriesOutput> field_output_;  // null without solver stages on a mesh
  std::shared_ptr<StatisticsOutput> statistics_;
};

/// File name of the run record inside the output directory.
inline constexpr const char* kRunRecordName = "run.yaml";

}  // namespace tessella::sim
