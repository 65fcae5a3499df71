// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Compartment (cell-level) transport from Python: one concentration per
// cell, passive and polar exchange across walls, no mesh. step/advance
// return the new concentrations (a NumPy array) instead of editing in place.
#include "bindings.hpp"
#include "tessella/solvers/compartment_transport.hpp"

namespace tessella::python {

// The API bound in this file, by its own names.
using namespace tessella::solvers;

namespace {

Eigen::VectorXd checkedConcentrations(const CompartmentTransport& ct, Eigen::VectorXd c) {
  if (c.size() != ct.numCells())
    throw InputError("compartment transport: " + std::to_string(c.size()) + " concentrations for " +
                     std::to_string(ct.numCells()) + " cells");
  return c;
}

}  // namespace

void bindCompartments(py::module_& m) {
  py::class_<CompartmentWall>(m, "CompartmentWall", "A wall between cells i and j (indices into the network).")
      .def(py::init([](int cell_i, int cell_j, double area, double permeability, double polar_ij, double polar_ji) {
             return CompartmentWall{.cell_i = cell_i, .cell_j = cell_j, .area = area, .permeability = permeability,
                                    .polar_ij = polar_ij, .polar_ji = polar_ji};
           }),
           py::arg("cell_i"), py::arg("cell_j"), py::arg("area"), py::arg("permeability") = 0.0,
           py::arg("polar_ij") = 0.0, py::arg("polar_ji") = 0.0)
      .def_readwrite("cell_i", &CompartmentWall::cell_i)
      .def_readwrite("cell_j", &CompartmentWall::cell_j)
      .def_readwrite("area", &CompartmentWall::area)
      .def_readwrite("permeability", &CompartmentWall::permeability)
      .def_readwrite("polar_ij", &CompartmentWall::polar_ij)
      .def_readwrite("polar_ji", &CompartmentWall::polar_ji);

  py::class_<CompartmentNetwork>(m, "CompartmentNetwork",
                                 "Cells (volumes, decay, production per cell) and the walls between them.")
      .def(py::init([](Eigen::VectorXd volume, std::vector<CompartmentWall> walls, std::optional<Eigen::VectorXd> decay,
                       std::optional<Eigen::VectorXd> production) {
             return CompartmentNetwork{std::move(volume), std::move(walls), decay.value_or(Eigen::VectorXd()),
                                       production.value_or(Eigen::VectorXd())};
           }),
           py::arg("volume"), py::arg("walls"), py::arg("decay") = py::none(), py::arg("production") = py::none())
      .def_readwrite("volume", &CompartmentNetwork::volume)
      .def_readwrite("walls", &CompartmentNetwork::walls)
      .def_readwrite("decay", &CompartmentNetwork::decay)
      .def_readwrite("production", &CompartmentNetwork::production);

  py::class_<CompartmentTransport>(m, "CompartmentTransport", R"doc(
V_i dc_i/dt = sum_walls [P A (c_j - c_i) - T_ij A c_i + T_ji A c_j] - k_i V_i c_i + p_i V_i.
The total amount sum V_i c_i is conserved to round-off when k = p = 0.
)doc")
      .def(py::init<CompartmentNetwork, TimeScheme>(), py::arg("network"), py::arg("scheme") = TimeScheme::ImplicitEuler)
      .def_property_readonly("num_cells", &CompartmentTransport::numCells)
      .def("rate", [](const CompartmentTransport& ct, Eigen::VectorXd c) { return ct.rate(checkedConcentrations(ct, std::move(c))); },
           py::arg("c"), "dc/dt at concentrations c.")
      .def("step",
           [](CompartmentTransport& ct, Eigen::VectorXd c, double dt) {
             c = checkedConcentrations(ct, std::move(c));
             ct.step(c, dt);
             return c;
           },
           py::arg("c"), py::arg("dt"), "The concentrations one step dt later (a new array).")
      .def("advance",
           [](CompartmentTransport& ct, Eigen::VectorXd c, double duration, double dt) {
             c = checkedConcentrations(ct, std::move(c));
             ct.advance(c, duration, dt);
             return c;
           },
           py::arg("c"), py::arg("duration"), py::arg("dt"), "The concentrations after ceil(duration/dt) equal steps.")
      .def("total_amount",
           [](const CompartmentTransport& ct, Eigen::VectorXd c) { return ct.totalAmount(checkedConcentrations(ct, std::move(c))); },
           py::arg("c"), "sum_i V_i c_i.");
}

}  // namespace tessella::python
