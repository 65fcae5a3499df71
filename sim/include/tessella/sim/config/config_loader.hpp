// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Reading a configuration: YAML text -> schema check -> Config.
//
// Everything is checked before anything is returned: unknown keys (with a
// "did you mean" suggestion), wrong types, out-of-range values, missing
// files, malformed YAML, duplicate keys and missing required keys each raise
// a ConfigError naming the file, line and column, the key path and the value.
//
// Overrides are "key.path=value" strings (the CLI's --set). The value is
// parsed as YAML, so `--set tissue.voronoi.domain={...}` sets a whole
// section; it is checked exactly like a file value, and errors name the
// override. Relative paths in overrides resolve against the working directory.

#include <string>
#include <vector>

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"

namespace tessella::sim {

/// Loads and validates a config file. Relative paths in it resolve against
/// the file's directory; the Config's name is the file's stem.
Config loadConfigFile(const std::string& path, const std::vector<std::string>& overrides,
                      const Schema& schema);

/// Loads and validates YAML text. `source` names it in messages; relative
/// paths resolve against `base_directory`.
Config loadConfigString(const std::string& yaml, const std::vector<std::string>& overrides,
                        const Schema& schema, const std::string& name = "simulation",
                        const std::string& source = "<string>",
                        const std::string& base_directory = ".");

}  // namespace tessella::sim
