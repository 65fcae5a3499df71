// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The configuration schema: every key a config file may hold, with its type,
// default, allowed range or choices, and a doc string. Validation, defaults,
// run.yaml and the reference in docs/config.md are all derived from it, so a
// key exists in exactly one place.
//
// Keys live in sections ("tissue", "tissue.voronoi", ...). A section or key
// can be conditional (`activeWhen`): tissue.voronoi only matters when
// tissue.generator is "voronoi". Inactive parts are validated when given but
// are not used and not written to run.yaml.
//
// A section can also be a map of named entries (`entryMap`): the user picks
// the entry names (diffusion.species_map.A, .B, ...) and every entry is a
// section with the keys declared once under the placeholder
// `<section>.<name>` (kEntryPlaceholder). Lookups of a concrete path
// (diffusion.species_map.A.decay) find the declaration of its template
// (diffusion.species_map.<name>.decay); the loader records the entry names
// given, in file order (Config::entryNames).
//
// A new config section is a unit {declare its keys, read them, make its
// stages} in the table sectionUnits() (sections/simulation_config.hpp);
// docs/extending.md, "Add a solver section".

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "tessella/sim/config/config_value.hpp"

namespace tessella::sim {

/// "Active when the Enum key `key` has one of `values`" (and `key` is active).
struct Condition {
  std::string key;
  std::vector<std::string> values;
};

struct KeySpec {
  std::string path;  ///< full dotted path, e.g. "tissue.voronoi.count"
  ValueType type = ValueType::String;
  std::string doc;
  /// Value used when the key is absent. No default: the key is required
  /// (`required`) or optional with a meaning given by `absent_doc`.
  std::optional<ConfigValue> default_value;
  bool required = false;
  std::string absent_doc;
  std::optional<double> min, max;  ///< Int and Float only
  bool min_exclusive = false, max_exclusive = false;
  std::vector<std::string> choices;  ///< Enum only
  std::optional<Condition> active_when;
  /// The key does not apply when this other key has a value (count vs
  /// seed_file), or this entry map has entries.
  std::string unless_set;

  // Fluent setters, so declarations read like a table.
  KeySpec& byDefault(ConfigValue v) { default_value = std::move(v); return *this; }
  KeySpec& isRequired() { required = true; return *this; }
  KeySpec& whenAbsent(std::string meaning) { absent_doc = std::move(meaning); return *this; }
  KeySpec& atLeast(double v) { min = v; min_exclusive = false; return *this; }
  KeySpec& above(double v) { min = v; min_exclusive = true; return *this; }
  KeySpec& atMost(double v) { max = v; max_exclusive = false; return *this; }
  KeySpec& oneOf(std::vector<std::string> c) { choices = std::move(c); return *this; }
  KeySpec& activeWhen(std::string key, std::vector<std::string> values) {
    active_when = Condition{std::move(key), std::move(values)};
    return *this;
  }
  KeySpec& unlessSet(std::string key) { unless_set = std::move(key); return *this; }

  /// The leaf name ("count" for "tissue.voronoi.count").
  std::string name() const;
  /// The allowed range in words ("> 0", ">= 3 and <= 1000"), or "" if none.
  std::string rangeText() const;
  /// The expected value in words: "an integer >= 3", "one of a, b".
  std::string expectation() const;
};

/// The entry name in the declared paths of an entry map's entries.
inline constexpr const char* kEntryPlaceholder = "<name>";

struct SectionSpec {
  std::string path;
  std::string doc;
  std::optional<Condition> active_when;
  /// A map of named entries, each declared as the section `<path>.<name>`.
  bool entry_map = false;
  /// What an entry stands for in messages ("species").
  std::string entry_kind;
  /// As KeySpec::unless_set.
  std::string unless_set;

  SectionSpec& unlessSet(std::string key) { unless_set = std::move(key); return *this; }
  SectionSpec& entryMap(std::string kind) {
    entry_map = true;
    entry_kind = std::move(kind);
    return *this;
  }

  SectionSpec& activeWhen(std::string key, std::vector<std::string> values) {
    active_when = Condition{std::move(key), std::move(values)};
    return *this;
  }
};

class Schema {
 public:
  /// Declares a section; its parent must be declared first ("" is the root).
  SectionSpec& section(std::string path, std::string doc);
  /// Declares a key in an already declared section. Throws std::logic_error
  /// on a duplicate path or an undeclared section (a programming error).
  KeySpec& key(std::string path, ValueType type, std::string doc);
  /// Declares the key `<section>.<param.name>` from a registry entry's
  /// parameter (tessella/tissue/registry.hpp): type, doc, default, range,
  /// choices; `unless_set` names a sibling key; a parameter with neither a
  /// default nor a meaning when absent is required.
  KeySpec& key(const std::string& section, const ParamSpec& param);

  /// Lookups take concrete paths (entry names in place of the placeholder).
  const KeySpec* findKey(const std::string& path) const;
  const SectionSpec* findSection(const std::string& path) const;
  bool isSection(const std::string& path) const { return path.empty() || findSection(path); }
  /// Whether `path` is an entry map (its children are named by the user).
  bool isEntryMap(const std::string& path) const;
  /// The declared path of a concrete one: each name following an entry map
  /// replaced by the placeholder ("d.species_map.A.decay" -> "d.species_map.<name>.decay").
  std::string templatePath(const std::string& path) const;

  /// Names (not paths) of a section's keys and subsections, in declaration
  /// order (for an entry map: the placeholder).
  std::vector<std::string> childNames(const std::string& section_path) const;
  /// Every key and every section, in declaration order.
  const std::deque<KeySpec>& keys() const { return keys_; }
  const std::deque<SectionSpec>& sections() const { return sections_; }

 private:
  std::deque<KeySpec> keys_;  // deque: references handed out stay valid
  std::deque<SectionSpec> sections_;
  std::vector<std::string> order_;  // every path, keys and sections, in declaration order
};

/// Joins a section path and a name ("" + "time" = "time").
std::string joinPath(const std::string& section, const std::string& name);
/// The section part of a path ("tissue.voronoi" for "tissue.voronoi.count").
std::string parentPath(const std::string& path);
/// The last part of a path ("count" for "tissue.voronoi.count").
std::string leafName(const std::string& path);
/// Whether a path holds the entry placeholder (a declared template, not a
/// concrete key).
bool isTemplatePath(const std::string& path);

}  // namespace tessella::sim
