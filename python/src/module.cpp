// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The Python module `tessella`: the C++ library's public API for models
// written in Python (docs/embedding.md, "Python").
#include "bindings.hpp"

PYBIND11_MODULE(tessella, m) {
  using namespace tessella::python;
  m.doc() = "Tessella: plant cell-tissue growth (tissues, growth fields, division, simulations, meshing and FE solvers, ParaView output).";
#ifdef TESSELLA_VERSION
  m.attr("__version__") = TESSELLA_VERSION;
#endif
  bindErrors(m);
  py::class_<tessella::Tissue> tissue = bindTissue(m);
  bindProperties(tissue);
  bindGenerators(m);
  bindGrowth(m);
  bindDivision(m);
  bindIo(m);
  bindLabelImage(m);
  bindSim(m);
  bindMesh(m);
  bindFieldTransfer(m);
  bindLinearSolver(m);  // before the solvers: their options default to LinearSolverOptions()
  bindDiffusion(m);     // before compartments and elasticity, which use TimeScheme
  bindCompartments(m);
  bindNetworks(m);
  bindElasticity(m);
}
