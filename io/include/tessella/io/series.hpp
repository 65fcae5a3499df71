// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// ParaView time series: DIR/<name>.pvd listing DIR/<name>_000000.vtu, ...
// with the simulation time of each step. The .pvd is rewritten (temporary
// file, then rename) after every step, so an interrupted run leaves a valid,
// openable series of the steps written so far.

#include <string>
#include <vector>

#include "tessella/io/pvd.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::io {

class SeriesWriter {
 public:
  /// Creates `directory` if needed. Throws InputError if it cannot be created.
  SeriesWriter(std::string directory, std::string name = "tissue", VtuOptions options = {});

  /// Writes one snapshot for simulation time `time` and updates the .pvd.
  /// Returns the snapshot's path.
  /// `state` is stored with it (RunState); `geometry` as for writeTissueVtu.
  std::string write(const Tissue& tissue, double time, const RunState& state = {},
                    GeometryCache* geometry = nullptr);

  /// Continues the series already on disk (an interrupted run resumed): its
  /// entries up to `last_time` are kept and the next write follows them;
  /// the files of later entries (with every file beside them, <stem>.*.vtu:
  /// field state, walls files) and leftover temporaries are deleted, and the
  /// beside series (setBesideSeries) are cut at the same time.
  /// InputError if the .pvd cannot be read or a file cannot be removed.
  void continueAfter(double last_time);

  /// The files for looking at that a run writes beside each snapshot,
  /// <stem>.<tag>.vtu (besideSnapshotPath, e.g. the walls files of
  /// wall_vtu.hpp), get a series each: <name>.<tag>.pvd lists, with its time,
  /// the file of every snapshot that has one when write() writes the snapshot
  /// (written before it). Set before the first write() or continueAfter().
  void setBesideSeries(std::vector<std::string> tags);
  /// <directory>/<name>.<tag>.pvd.
  std::string besidePvdPath(const std::string& tag) const;

  const std::string& pvdPath() const { return pvd_path_; }
  std::size_t steps() const { return entries_.size(); }
  /// The path the next write() writes to (for files written beside it first).
  std::string nextPath() const;
  const VtuOptions& options() const { return options_; }

 private:
  struct Entry {
    double time;
    std::string file;  // relative to the directory
  };
  struct Beside {
    std::string tag;
    std::vector<PvdEntry> entries;
  };
  void writePvd() const;

  std::string directory_;
  std::string name_;
  std::string pvd_path_;
  VtuOptions options_;
  std::vector<Entry> entries_;
  std::vector<Beside> beside_;
};

}  // namespace tessella::io
