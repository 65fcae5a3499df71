// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Registry: one table per extensible concept (division rules, thresholds,
// velocity fields, generators, ...). An entry is a name, a doc string, the
// parameters it reads (parameters.hpp) and its factory. The YAML schema and
// readers, the CLI, the Python bindings and docs/config.md all read the
// table, so adding an entry is one line in the table and nothing else.
//
//   const Registry<RuleFactory>& rules = divisionRules();
//   auto rule = rules.make("besson_dumais", {{"beta", 5.0}});
//
// `Factory` is the entry's function type; make() passes it the completed
// parameter values first, then any further arguments.

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/parameters.hpp"

namespace tessella {

/// The `name` of every entry, in order (registries and enum tables).
template <typename Entries>
std::vector<std::string> entryNames(const Entries& entries) {
  std::vector<std::string> out;
  for (const auto& e : entries) out.push_back(e.name);
  return out;
}

/// "a, b, c".
inline std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

template <typename Factory>
struct RegistryEntry {
  std::string name;
  std::string doc;
  std::vector<ParamSpec> params;
  Factory make;
};

template <typename Factory>
class Registry {
 public:
  using Entry = RegistryEntry<Factory>;

  /// `kind` names an entry in messages ("division rule").
  Registry(std::string kind, std::vector<Entry> entries) : kind_(std::move(kind)) {
    for (auto& e : entries) add(std::move(e));
  }

  /// Adds an entry; a duplicate name is a programming error (std::logic_error).
  void add(Entry entry) {
    if (find(entry.name)) throw std::logic_error(kind_ + " '" + entry.name + "' is registered twice");
    entries_.push_back(std::move(entry));
  }

  const std::string& kind() const { return kind_; }
  const std::vector<Entry>& entries() const { return entries_; }
  std::vector<std::string> names() const { return entryNames(entries_); }
  /// "a, b, c": the names for messages and docs.
  std::string namesText() const { return joinNames(names()); }

  const Entry* find(std::string_view name) const {
    for (const auto& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }
  /// InputError naming the value and listing the known names when unknown.
  const Entry& at(std::string_view name) const {
    if (const Entry* e = find(name)) return *e;
    throw InputError("unknown " + kind_ + " '" + std::string(name) + "' (known: " + namesText() + ")");
  }

  /// The entry's product from `values` (defaults filled in, every value
  /// checked: InputError naming the entry and the parameter).
  template <typename... Args>
  auto make(std::string_view name, const ParamValues& values, Args&&... args) const {
    const Entry& e = at(name);
    return e.make(completeParams(e.params, values, kind_ + " '" + e.name + "'"), std::forward<Args>(args)...);
  }

 private:
  std::string kind_;
  std::vector<Entry> entries_;
};

}  // namespace tessella
