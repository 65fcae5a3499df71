// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// EnumTable: the names of an enum's values, for the choices a user makes by
// name that take no parameters (an integration scheme, where velocities come
// from). The counterpart of registry.hpp for plain enums: the YAML schema's
// choices, the readers, the Python bindings and the generated docs all read
// the one table, so a value is named in exactly one place.
//
//   const EnumTable<Scheme> schemes("integration scheme", {{"euler", Scheme::Euler, "Explicit Euler."}});
//   Scheme s = schemes.parse("euler");   // InputError listing the names for an unknown one

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/registry.hpp"

namespace tessella {

template <typename E>
struct EnumEntry {
  std::string name;
  E value;
  std::string doc;
};

template <typename E>
class EnumTable {
 public:
  /// `kind` names a value in messages ("integration scheme"). `aliases` are
  /// further names parse() accepts (kept for old scripts); they are not
  /// choices and not documented.
  EnumTable(std::string kind, std::vector<EnumEntry<E>> entries, std::vector<std::pair<std::string, E>> aliases = {})
      : kind_(std::move(kind)), entries_(std::move(entries)), aliases_(std::move(aliases)) {
    for (std::size_t i = 0; i < entries_.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (entries_[i].name == entries_[j].name)
          throw std::logic_error(kind_ + " '" + entries_[i].name + "' is named twice");
  }

  const std::string& kind() const { return kind_; }
  const std::vector<EnumEntry<E>>& entries() const { return entries_; }
  std::vector<std::string> names() const { return entryNames(entries_); }
  /// "a, b, c": the names for messages and docs (aliases not included).
  std::string namesText() const { return joinNames(names()); }

  /// The value named `name` (or an alias); InputError naming the value and
  /// listing the accepted names otherwise.
  E parse(std::string_view name) const {
    for (const auto& e : entries_)
      if (e.name == name) return e.value;
    for (const auto& [alias, value] : aliases_)
      if (alias == name) return value;
    std::string known = namesText();
    for (const auto& a : aliases_) known += ", " + a.first;
    throw InputError("unknown " + kind_ + " '" + std::string(name) + "' (known: " + known + ")");
  }

  /// The name of a value; std::logic_error when the table lacks it (a
  /// programming error: every enumerator has an entry).
  const std::string& name(E value) const {
    for (const auto& e : entries_)
      if (e.value == value) return e.name;
    throw std::logic_error(kind_ + ": a value without a name");
  }

 private:
  std::string kind_;
  std::vector<EnumEntry<E>> entries_;
  std::vector<std::pair<std::string, E>> aliases_;
};

}  // namespace tessella
