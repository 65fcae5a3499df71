// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Config: a validated configuration. Every key of the schema that is active
// has a value here (from the file, a --set override or the default), with the
// place it came from, so later checks can still point at the right line.
//
// Build one with loadConfigFile() / loadConfigString() (config_loader.hpp):
// a Config is never half-valid.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "tessella/sim/config/config_error.hpp"
#include "tessella/sim/config/config_value.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/tissue/parameters.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::sim {

class Config {
 public:
  struct Entry {
    ConfigValue value;
    SourceLocation where;  ///< empty for defaults
    ValueOrigin origin = ValueOrigin::Default;
  };

  /// An empty configuration (no values yet) over `schema`, which must outlive it.
  /// `name` names the run (the config file's stem); `base_directory` is where
  /// relative paths in the file are resolved from.
  Config(const Schema& schema, std::string name, std::string source, std::string base_directory);

  const Schema& schema() const { return *schema_; }
  /// The config file's stem ("hex_grid_2d"), used for the default output directory.
  const std::string& name() const { return name_; }
  /// The config file path (or "<string>").
  const std::string& source() const { return source_; }
  const std::string& baseDirectory() const { return base_directory_; }

  /// Has a value (given or defaulted).
  bool has(const std::string& path) const { return entries_.count(path) > 0; }
  /// Was given explicitly, in the file or by an override.
  bool isGiven(const std::string& path) const;
  /// A key with a value, or an entry map with entries.
  bool isSet(const std::string& path) const { return has(path) || entry_names_.count(path) > 0; }
  /// The entry of a key that has a value; std::logic_error otherwise (a
  /// programming error: the schema guarantees values of active keys).
  const Entry& entry(const std::string& path) const;

  bool getBool(const std::string& path) const;
  std::int64_t getInt(const std::string& path) const;
  double getFloat(const std::string& path) const;
  /// String, Enum and Path keys (Path values are absolute after loading).
  const std::string& getString(const std::string& path) const;
  /// Vec2 keys give z = 0.
  Vec3 getVec(const std::string& path) const;

  /// The values of `params` under `section` (the key `<section>.<name>` of
  /// each parameter that has a value), for a registry entry's factory
  /// (tessella/tissue/registry.hpp; sim/config/registry_config.hpp).
  ParamValues params(const std::string& section, const std::vector<ParamSpec>& params) const;

  /// Whether a key or section matters under the current values (all the
  /// conditions along its path hold).
  bool isActive(const std::string& path) const;

  /// The entry names given in an entry map section (schema.hpp), in the order
  /// they were first given.
  std::vector<std::string> entryNames(const std::string& map_path) const;
  /// Records an entry of an entry map (loaders); a known name is kept once.
  void addEntry(const std::string& map_path, const std::string& name, SourceLocation where);
  /// Where an entry was first given (empty if unknown).
  SourceLocation entryLocation(const std::string& entry_path) const;

  /// Sets a value (loaders, and derived values such as the RNG seed used).
  void set(const std::string& path, ConfigValue value, SourceLocation where, ValueOrigin origin);
  void erase(const std::string& path) { entries_.erase(path); }
  const std::map<std::string, Entry>& entries() const { return entries_; }

  /// A ConfigError located at the key (its file position when it was given).
  ConfigError errorAt(const std::string& path, const std::string& problem) const;

  /// Remarks that are not errors (e.g. a section that is given but unused
  /// under the chosen generator). Library code does not print: apps/ does.
  const std::vector<std::string>& notes() const { return notes_; }
  void addNote(std::string note) { notes_.push_back(std::move(note)); }

 private:
  bool conditionHolds(const Condition& c) const;

  const Schema* schema_;
  std::string name_;
  std::string source_;
  std::string base_directory_;
  std::map<std::string, Entry> entries_;
  std::map<std::string, std::vector<std::string>> entry_names_;  // map path -> names in order
  std::map<std::string, SourceLocation> entry_where_;              // entry path -> where given
  std::vector<std::string> notes_;
};

}  // namespace tessella::sim
