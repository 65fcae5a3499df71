// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// ConfigError: a configuration problem, reported before any work starts.
// The message always reads "<where>: <key path>: <problem>", e.g.
//   run.yaml:12:10: tissue.voronoi.count: expected an integer >= 3, got 1

#include <string>

#include "tessella/sim/config/config_value.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::sim {

class ConfigError : public InputError {
 public:
  /// key_path may be empty for whole-file problems (malformed YAML).
  ConfigError(SourceLocation where, std::string key_path, std::string problem);

  const SourceLocation& where() const { return where_; }
  const std::string& keyPath() const { return key_path_; }
  /// The problem alone, without location and key path.
  const std::string& problem() const { return problem_; }

 private:
  SourceLocation where_;
  std::string key_path_;
  std::string problem_;
};

}  // namespace tessella::sim
