// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Python values as the parameters of a registry entry (a division rule, a
// velocity field: tessella/tissue/registry.hpp). Each keyword argument is
// converted by the declared type of the parameter of that name, and the
// docstrings list the entries with their parameters from the same table.
#include <string>
#include <vector>

#include "bindings.hpp"
#include "tessella/tissue/registry.hpp"

namespace tessella::python {

inline ParamValue paramValueFromPython(const ParamSpec& spec, py::handle value) {
  try {
    switch (spec.type) {
      case ParamType::Bool: return value.cast<bool>();
      case ParamType::Int: return static_cast<std::int64_t>(value.cast<long long>());
      case ParamType::Float: return value.cast<double>();
      case ParamType::String:
      case ParamType::Enum:
      case ParamType::Path: return value.cast<std::string>();
      case ParamType::Vec2:
      case ParamType::Vec3:
      case ParamType::Vec2or3: return value.cast<std::vector<double>>();
    }
  } catch (const py::cast_error&) {
  }
  throw InputError("parameter '" + spec.name + "' must be a " + paramTypeName(spec.type) + ", got " +
                   std::string(py::repr(value)));
}

/// The parameter `name` of `entry`, or null.
template <typename Entry>
const ParamSpec* findParam(const Entry& entry, const std::string& name) {
  for (const ParamSpec& p : entry.params)
    if (p.name == name) return &p;
  return nullptr;
}

/// "  name: doc Parameters: p (default 1.0) doc." for every entry: the
/// docstring part of a make_* function.
template <typename Factory>
std::string registryDoc(const Registry<Factory>& registry) {
  std::string out;
  for (const auto& e : registry.entries()) {
    out += "\n  " + e.name + ": " + e.doc;
    for (const ParamSpec& p : e.params)
      out += "\n      " + p.name + " (" + paramTypeName(p.type) +
             (p.default_value ? ", default " + formatParamValue(*p.default_value) : std::string()) + "): " + p.doc;
  }
  return out;
}

}  // namespace tessella::python
