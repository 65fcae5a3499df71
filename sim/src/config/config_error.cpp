// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/config/config_error.hpp"

namespace tessella::sim {

namespace {
std::string compose(const SourceLocation& where, const std::string& key, const std::string& problem) {
  std::string s;
  if (where.known()) s += where.str() + ": ";
  if (!key.empty()) s += key + ": ";
  return s + problem;
}
}  // namespace

ConfigError::ConfigError(SourceLocation where, std::string key_path, std::string problem)
    : InputError(compose(where, key_path, problem)),
      where_(std::move(where)),
      key_path_(std::move(key_path)),
      problem_(std::move(problem)) {}

}  // namespace tessella::sim
