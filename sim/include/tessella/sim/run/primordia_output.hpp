// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// PrimordiaOutput: DIR/primordia.csv, one row per primordium the network
// stage found (NetworkSpec::primordia): time, lineage id of its cell, the
// cell's centroid, its angle about the dome's axis, its distances from the
// axis (radius) and from the apex (distance) and the divergence angle from the previous primordium (empty for the
// first). The file is rewritten from the stage's records whenever one is
// added, so a resumed run (whose records come from the snapshot's run state)
// writes the same file as the uninterrupted one.

#include <memory>
#include <string>

#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/network_stage.hpp"

namespace tessella::sim {

/// File name of the primordia table inside the output directory.
inline constexpr const char* kPrimordiaName = "primordia.csv";

/// The CSV text of the records (header and one row per primordium).
std::string primordiaCsv(const std::vector<PrimordiumRecord>& records);

/// When the simulation has a network stage with primordium detection: writes
/// the file now (the records so far) and again after every step that adds
/// one; returns the stage (null and nothing written when there is none).
const NetworkStage* attachPrimordiaOutput(Simulation& simulation, const std::string& directory);

}  // namespace tessella::sim
