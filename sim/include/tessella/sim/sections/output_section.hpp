// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The `output:` section: where and how often the ParaView series is written.

#include <cstddef>
#include <string>

#include "tessella/io/vtu.hpp"
#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"

namespace tessella::sim {

struct OutputSpec {
  /// Empty: runs/<config name> relative to the working directory.
  std::string directory;
  /// Series name: DIR/<name>.pvd and DIR/<name>_NNNNNN.vtu.
  std::string name = "tissue";
  /// A snapshot every `every` steps (plus the initial and the final state).
  std::size_t every = 1;
  io::VtuOptions vtu;
};

void declareOutputSection(Schema& schema);
/// Reads output.*; a series name that is not a plain file name is a ConfigError.
OutputSpec readOutputSection(const Config& config);

}  // namespace tessella::sim
