// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Tessella's C++ errors as Python exceptions, message unchanged:
//   tessella.Error            (RuntimeError)  base of all below
//   tessella.InputError       (Error, ValueError)  bad input: parameters, files, YAML
//   tessella.GeometryError    (Error)  degenerate geometry (a plane missing a cell)
//   tessella.TopologyError    (Error)  an edit that would break the complex
//   tessella.SimulationError  (Error)  a stage failed; names stage, step and time
// InputError derives from ValueError so that `except ValueError` works as
// Python code expects for bad arguments. The solvers' errors (SolverError, a
// tessella::Error) map onto these: InvalidProblemError (a badly posed problem)
// -> InputError; FactorizationError, ConvergenceError -> Error.
#include "bindings.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/solvers/errors.hpp"

namespace tessella::python {

namespace {

// The module's attribute holds the reference; the returned handle borrows it
// (a static py::object would be released after the interpreter is gone).
py::handle newException(py::module_& m, const char* name, py::tuple bases, const char* doc) {
  const std::string qualified = std::string("tessella.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!type) throw py::error_already_set();
  m.attr(name) = py::reinterpret_steal<py::object>(type);
  return type;
}

}  // namespace

void bindErrors(py::module_& m) {
  static py::handle error = newException(m, "Error", py::make_tuple(py::handle(PyExc_RuntimeError)),
                                         "Base of every error Tessella raises on purpose.");
  static py::handle input = newException(m, "InputError", py::make_tuple(error, py::handle(PyExc_ValueError)),
                                         "Bad input: parameters, files, configuration keys.");
  static py::handle geometry = newException(m, "GeometryError", py::make_tuple(error),
                                            "Degenerate or invalid geometry; the tissue is unchanged.");
  static py::handle topology = newException(m, "TopologyError", py::make_tuple(error),
                                            "An edit or a build would break the cell complex.");
  static py::handle simulation = newException(m, "SimulationError", py::make_tuple(error),
                                              "A simulation stage failed (names stage, step and time).");

  // Most derived first: translators are tried in reverse registration order,
  // and one catch clause chain handles every type.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const sim::SimulationError& e) {
      PyErr_SetString(simulation.ptr(), e.what());
    } catch (const InputError& e) {
      PyErr_SetString(input.ptr(), e.what());
    } catch (const GeometryError& e) {
      PyErr_SetString(geometry.ptr(), e.what());
    } catch (const TopologyError& e) {
      PyErr_SetString(topology.ptr(), e.what());
    } catch (const solvers::InvalidProblemError& e) {
      PyErr_SetString(input.ptr(), e.what());
    } catch (const Error& e) {  // SolverError and its other kinds too
      PyErr_SetString(error.ptr(), e.what());
    }
  });
}

}  // namespace tessella::python
