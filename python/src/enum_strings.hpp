// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// C++ enums as Python enums that also accept their snake_case name, so
// options read like the rest of the module (scheme="heun"):
//   DiffusionOptions(scheme="crank_nicolson") == DiffusionOptions(scheme=TimeScheme.CrankNicolson)
// An unknown name is an InputError (ValueError) listing the accepted ones.
#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "tessella/tissue/enum_table.hpp"

namespace tessella::python {

template <typename E>
py::enum_<E> bindEnum(py::module_& m, const char* name, const char* doc,
                      std::vector<std::pair<std::string, std::pair<std::string, E>>> values) {
  py::enum_<E> e(m, name, doc);
  for (const auto& [snake, named] : values) e.value(named.first.c_str(), named.second);
  e.def(py::init([name, values](const std::string& s) {
          std::string known;
          for (const auto& [snake, named] : values) {
            if (s == snake || s == named.first) return named.second;
            known += (known.empty() ? "" : ", ") + snake;
          }
          throw InputError(std::string(name) + ": unknown value '" + s + "' (expected one of " + known + ")");
        }),
        py::arg("name"));
  py::implicitly_convertible<py::str, E>();
  return e;
}

/// "crank_nicolson" -> "CrankNicolson".
inline std::string camelCase(const std::string& snake) {
  std::string out;
  bool upper = true;
  for (char ch : snake) {
    if (ch == '_') {
      upper = true;
      continue;
    }
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(ch))) : ch;
    upper = false;
  }
  return out;
}

/// The values of the enum's table (the module defining the enum names them):
/// members in CamelCase, the table's names accepted as strings.
template <typename E>
py::enum_<E> bindEnum(py::module_& m, const char* name, const char* doc, const EnumTable<E>& table) {
  std::vector<std::pair<std::string, std::pair<std::string, E>>> values;
  for (const auto& entry : table.entries()) values.push_back({entry.name, {camelCase(entry.name), entry.value}});
  return bindEnum(m, name, doc, std::move(values));
}

}  // namespace tessella::python
