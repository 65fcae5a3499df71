// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// SeriesOutput: writes a Simulation's tissue as a ParaView series
// (io::SeriesWriter) on a schedule: the initial state, every `every` steps,
// and the final state, each time exactly once.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "tessella/io/series.hpp"
#include "tessella/sim/sections/output_section.hpp"
#include "tessella/sim/simulation.hpp"

namespace tessella::sim {

class SeriesOutput {
 public:
  /// Creates the directory (through io::SeriesWriter).
  SeriesOutput(const std::string& directory, const OutputSpec& spec);

  /// Writes the current state if due at the simulation's current step.
  void writeIfDue(const Simulation& simulation);
  /// Writes the current state now (once per step: a second call is a no-op).
  void write(const Simulation& simulation);
  /// The files the stages write beside each snapshot (Stage::besideFileTags)
  /// get a series each, <name>.<tag>.pvd. Before the first write or continueAfter.
  void listBesideFiles(const Simulation& simulation);
  /// Continues the series on disk after `time` (io::SeriesWriter::continueAfter).
  void continueAfter(const Simulation& simulation, double time);

  std::size_t snapshots() const { return writer_.steps(); }
  const std::string& pvdPath() const { return writer_.pvdPath(); }
  /// <directory>/<name>.<tag>.pvd, the series of the files beside the snapshots with `tag`.
  std::string besidePvdPath(const std::string& tag) const { return writer_.besidePvdPath(tag); }

 private:
  io::SeriesWriter writer_;
  std::size_t every_;
  std::size_t last_written_step_ = static_cast<std::size_t>(-1);
};

/// Writes the current state now and registers a step callback that keeps the
/// series (and the series of the files the stages write beside it) up to date. The callback owns the returned output.
/// `resume_after`: continue the series already in `directory` (a resumed
/// run): its entries up to that time stay, later ones are deleted, and the
/// current state, already on disk, is not written again.
std::shared_ptr<SeriesOutput> attachSeriesOutput(Simulation& simulation, const std::string& directory,
                                                 const OutputSpec& spec,
                                                 std::optional<double> resume_after = std::nullopt);

/// Number of snapshots a run of `steps` steps writes with output every `every`.
std::size_t expectedSnapshots(std::size_t steps, std::size_t every);

}  // namespace tessella::sim
