// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// run.yaml: the fully resolved configuration of a run (every active key,
// defaults filled in, paths absolute, the RNG seed actually used and the
// Tessella version). `tessella run DIR/run.yaml --out OTHER` reproduces it.

#include <string>

#include "tessella/sim/config/config.hpp"

namespace tessella::sim {

/// The YAML text of a resolved configuration: active keys only, in schema
/// order, floats in shortest round-trip form (re-reading gives the same bits).
std::string resolvedConfigYaml(const Config& config);

/// Writes resolvedConfigYaml() to `path` atomically (temporary file, rename).
/// Throws InputError naming the path and the operating system's reason if it
/// cannot be written; no temporary file is left behind.
void writeRunRecord(const Config& config, const std::string& path);

}  // namespace tessella::sim
