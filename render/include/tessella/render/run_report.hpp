// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A run's report: `tessella report RUN_DIR` writes RUN_DIR/report.html with
// the run's configuration, plots made with matplotlib (cell count and cell
// size distribution over time, division orientations, solver field totals)
// and frames of the tissue (render/picture.hpp).
//
// This side gathers the data (frames, one row per cell per snapshot, one row
// per division) into RUN_DIR/report/; the plotting and the page are the
// Python script apps/report/tessella_report.py (matplotlib), which it runs.

#include <string>

namespace tessella::render {

struct RunReportOptions {
  /// Cell property the frames are coloured by ("size": area or volume).
  std::string property = "size";
  /// At most this many snapshots are read (evenly spaced, the last always).
  int max_snapshots = 40;
  /// At most this many frames are drawn.
  int max_frames = 8;
  /// The Python script that makes the page; "" finds it (TESSELLA_REPORT_SCRIPT,
  /// then PREFIX/share/tessella beside the program, then the source tree).
  std::string script;
};

struct RunReport {
  std::string html;      ///< RUN_DIR/report.html
  int snapshots = 0;     ///< snapshots read
  int frames = 0;        ///< frames drawn
  int divisions = 0;     ///< divisions found between the snapshots read
};

/// InputError naming the file for a directory that is not a run (no
/// tissue.pvd, stats.csv or run.yaml), a damaged snapshot, or a script that
/// fails (its message quoted).
RunReport writeRunReport(const std::string& run_dir, const RunReportOptions& options = {});

}  // namespace tessella::render
