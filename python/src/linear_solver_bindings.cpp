// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The linear-solver choice shared by every FE solver: which back-end
// (SolverMethod, solver_available), its options, and the report of a solve.
#include "bindings.hpp"
#include "enum_strings.hpp"
#include "tessella/solvers/linear_solver.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::python {

// The API bound in this file, by its own names.
using namespace tessella::solvers;

void bindLinearSolver(py::module_& m) {
  bindEnum<SolverMethod>(m, "SolverMethod",
                         "Linear solver back-end; cholmod and amg_cg exist only in builds with "
                         "TESSELLA_WITH_CHOLMOD / TESSELLA_WITH_HYPRE (see solver_available).",
                         {{"auto", {"Auto", SolverMethod::Auto}},
                          {"direct", {"Direct", SolverMethod::Direct}},
                          {"conjugate_gradient", {"ConjugateGradient", SolverMethod::ConjugateGradient}},
                          {"cholmod", {"Cholmod", SolverMethod::Cholmod}},
                          {"amg_cg", {"AmgCG", SolverMethod::AmgCG}}});
  bindEnum<Preconditioner>(m, "Preconditioner", "Preconditioner of Eigen's conjugate gradients.",
                           {{"jacobi", {"Jacobi", Preconditioner::Jacobi}},
                            {"incomplete_cholesky", {"IncompleteCholesky", Preconditioner::IncompleteCholesky}}});
  m.def("solver_available", &solverAvailable, py::arg("method"),
        "Whether this build contains the back-end (auto, direct and conjugate_gradient always are).");

  py::class_<LinearSolverOptions>(m, "LinearSolverOptions", "Options of the sparse SPD solve inside every solver.")
      .def(py::init([](SolverMethod method, Preconditioner preconditioner, double tolerance, int max_iterations,
                       int auto_direct_max_unknowns, double amg_strong_threshold, double pivot_tolerance) {
             return LinearSolverOptions{.method = method, .preconditioner = preconditioner, .tolerance = tolerance,
                                        .max_iterations = max_iterations,
                                        .auto_direct_max_unknowns = auto_direct_max_unknowns,
                                        .amg_strong_threshold = amg_strong_threshold,
                                        .pivot_tolerance = pivot_tolerance};
           }),
           py::arg("method") = SolverMethod::Auto, py::arg("preconditioner") = Preconditioner::IncompleteCholesky,
           py::arg("tolerance") = 1e-10, py::arg("max_iterations") = 0, py::arg("auto_direct_max_unknowns") = 100000,
           py::arg("amg_strong_threshold") = 0.5, py::arg("pivot_tolerance") = 1e-12)
      .def_readwrite("method", &LinearSolverOptions::method)
      .def_readwrite("preconditioner", &LinearSolverOptions::preconditioner)
      .def_readwrite("tolerance", &LinearSolverOptions::tolerance, "CG stops at ||b - A x|| <= tolerance ||b||.")
      .def_readwrite("max_iterations", &LinearSolverOptions::max_iterations, "CG cap; 0 = 2 x unknowns.")
      .def_readwrite("auto_direct_max_unknowns", &LinearSolverOptions::auto_direct_max_unknowns)
      .def_readwrite("amg_strong_threshold", &LinearSolverOptions::amg_strong_threshold)
      .def_readwrite("pivot_tolerance", &LinearSolverOptions::pivot_tolerance);

  py::class_<SolveReport>(m, "SolveReport", "What the last linear solve did.")
      .def_readonly("method", &SolveReport::method, "The back-end actually used (auto resolved).")
      .def_readonly("unknowns", &SolveReport::unknowns)
      .def_readonly("iterations", &SolveReport::iterations, "CG iterations (0 for direct solvers).")
      .def_readonly("relative_residual", &SolveReport::relative_residual, "||b - A x|| / ||b||.")
      .def("__repr__", [](const SolveReport& r) {
        return "SolveReport(method=" + toString(r.method) + ", unknowns=" + std::to_string(r.unknowns) +
               ", iterations=" + std::to_string(r.iterations) +
               ", relative_residual=" + formatNumber(r.relative_residual, 6) + ")";
      });
}

}  // namespace tessella::python
