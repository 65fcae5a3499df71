// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Conventions shared by the tissue and mesh series writers.

#include <string>
#include <vector>

#include "tessella/io/pvd.hpp"

namespace tessella::io::detail {

/// A series name becomes part of file names: non-empty, no path separators.
void checkSeriesName(const std::string& name);
/// Creates the directory (and parents) if needed; InputError naming it otherwise.
void createSeriesDirectory(const std::string& directory);
/// <name>_000042.vtu (6 digits, more when a run goes past a million steps).
std::string stepFileName(const std::string& name, std::size_t step);
/// Times must be finite and strictly increasing: ParaView would merge two
/// steps with the same time into one. `previous` is null for the first step.
void checkNextTime(const std::string& pvd_path, const double* previous, double time);

/// Continues a series on disk at `last_time` (an interrupted run resumed):
/// the entries of `pvd_path` up to that time stay, the files of later ones
/// (and every file beside them, <stem>.<tag>.vtu: field state, walls files)
/// and the temporaries of `<name>_*` and `<name>.*` an interrupted write left are deleted,
/// and the .pvd is rewritten. Returns the entries kept (none when there is
/// no .pvd). InputError naming the file that cannot be read or removed.
std::vector<PvdEntry> truncateSeries(const std::string& pvd_path, const std::string& name, double last_time,
                                     bool durable);

}  // namespace tessella::io::detail
