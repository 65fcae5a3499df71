// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Registries (tessella/tissue/registry.hpp) and enum tables
// (tessella/tissue/enum_table.hpp) in the configuration: a section declares
// its selector key's choices and the entries' parameters from the table, and
// reads an entry's values and makes it in one call, so a new table entry
// needs no edit here or in the section.
//
//   s.key("growth.field", ValueType::Enum, "...").oneOf(withNone(fields.names()));
//   declareEntrySections(s, "growth", "growth.field", fields);   // growth.<field>.<param>
//   auto field = makeFromConfig(c, fields, name, "growth." + name, "growth.field");
//
// Two layouts of the parameters: each entry in a section of its own under
// the parent (declareEntrySections: growth.bump.h), or all entries' keys
// directly in one section (declareEntryKeys: division.beta), each active when
// the selector names an entry that reads it.

#include <string>
#include <utility>
#include <vector>

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/tissue/enum_table.hpp"
#include "tessella/tissue/registry.hpp"

namespace tessella::sim {

/// "none" followed by `names`: the choices of a selector whose feature is off by default.
inline std::vector<std::string> withNone(std::vector<std::string> names) {
  names.insert(names.begin(), "none");
  return names;
}

/// "`a`: doc of a `b`: doc of b": the choices in a selector key's doc.
template <typename Table>
std::string choicesDoc(const Table& table) {
  std::string out;
  for (const auto& e : table.entries()) out += (out.empty() ? "`" : " `") + e.name + "`: " + e.doc;
  return out;
}

/// For every entry with parameters, the section `<parent>.<entry name>` (its
/// doc is the entry's, active when `selector` names the entry) with one key
/// per parameter.
template <typename Factory>
void declareEntrySections(Schema& s, const std::string& parent, const std::string& selector,
                          const Registry<Factory>& registry) {
  for (const auto& e : registry.entries()) {
    if (e.params.empty()) continue;
    const std::string section = joinPath(parent, e.name);
    s.section(section, e.doc).activeWhen(selector, {e.name});
    for (const ParamSpec& p : e.params) s.key(section, p);
  }
}

/// Every entry's parameters as keys of `section` itself, each active when
/// `selector` names an entry that reads it. A parameter several entries read
/// is one key; their declarations must agree (std::logic_error otherwise, a
/// programming error caught by the schema tests).
template <typename Factory>
void declareEntryKeys(Schema& s, const std::string& section, const std::string& selector,
                      const Registry<Factory>& registry) {
  std::vector<std::pair<const ParamSpec*, std::vector<std::string>>> keys;  // in first-use order
  for (const auto& e : registry.entries())
    for (const ParamSpec& p : e.params) {
      auto it = keys.begin();
      while (it != keys.end() && it->first->name != p.name) ++it;
      if (it == keys.end()) {
        keys.push_back({&p, {e.name}});
        continue;
      }
      const ParamSpec& q = *it->first;
      const bool same = q.type == p.type && q.doc == p.doc && q.default_value == p.default_value &&
                        q.absent_doc == p.absent_doc && q.range.min == p.range.min && q.range.max == p.range.max &&
                        q.range.min_exclusive == p.range.min_exclusive &&
                        q.range.max_exclusive == p.range.max_exclusive && q.choices == p.choices;
      if (!same)
        throw std::logic_error(registry.kind() + " '" + e.name + "': parameter '" + p.name +
                               "' differs from another entry's parameter of that name (both are the key " +
                               joinPath(section, p.name) + ")");
      it->second.push_back(e.name);
    }
  for (const auto& [param, readers] : keys) s.key(section, *param).activeWhen(selector, readers);
}

/// The entry `name` of `registry`, made from the values of its parameters
/// under `section` (Config::params) and `args`. A ParamError is a ConfigError
/// at that parameter's key, any other InputError one at `selector`.
template <typename Factory, typename... Args>
auto makeFromConfig(const Config& c, const Registry<Factory>& registry, const std::string& name,
                    const std::string& section, const std::string& selector, Args&&... args) {
  try {
    return registry.make(name, c.params(section, registry.at(name).params), std::forward<Args>(args)...);
  } catch (const ParamError& e) {
    throw c.errorAt(joinPath(section, e.param()), e.what());
  } catch (const InputError& e) {
    throw c.errorAt(selector, e.what());
  }
}

/// The value of `table` named by the key `key`; ConfigError at the key for an
/// unknown name (the schema's choices normally refuse it first).
template <typename E>
E parseFromConfig(const Config& c, const EnumTable<E>& table, const std::string& key) {
  try {
    return table.parse(c.getString(key));
  } catch (const InputError& e) {
    throw c.errorAt(key, e.what());
  }
}

}  // namespace tessella::sim
