#pragma once
// C++ enums as Python enums that also accept their snake_case name, so
// options read like the rest of the module (scheme="heun"):
//   DiffusionOptions(scheme="crank_nicolson") == DiffusionOptions(scheme=TimeScheme.CrankNicolson)
// An unknown name is an InputError (ValueError) listing the accepted ones.
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"

namespace tessella::python {

template <typename E>
py::enum_<E> bindEnum(py::module_& m, const char* name, const char* doc,
                      std::vector<std::pair<std::string, std::pair<const char*, E>>> values) {
  py::enum_<E> e(m, name, doc);
  for (const auto& [snake, named] : values) e.value(named.first, named.second);
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

}  // namespace tessella::python
