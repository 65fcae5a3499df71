// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Carrying fields from one tissue mesh to the next (growth and division in
// between): nodal P1 interpolation, amount-preserving concentration transfer
// and cell-wise amounts shared by lineage.
#include "bindings.hpp"
#include "tessella/mesh/field_transfer.hpp"

namespace tessella::python {

// The API bound in this file, by its own names.
using namespace tessella::mesh;

void bindFieldTransfer(py::module_& m) {
  m.def("ancestor_cells", py::overload_cast<const Tissue&, const Tissue&>(&ancestorCells), py::arg("old_tissue"),
        py::arg("new_tissue"),
        "Per cell slot of new_tissue: the old cell it comes from (lineage, then parent), -1 for dead slots.");
  m.def("interpolate_nodal_field",
        py::overload_cast<const Tissue&, const FeMesh&, const Eigen::VectorXd&, const Tissue&, const FeMesh&>(
            &interpolateNodalField), py::arg("old_tissue"), py::arg("old_mesh"),
        py::arg("old_field"), py::arg("new_tissue"), py::arg("new_mesh"),
        "P1 interpolation of a nodal field onto new_mesh, locating nodes by cell lineage.");
  m.def("transfer_concentration",
        py::overload_cast<const Tissue&, const FeMesh&, const Eigen::VectorXd&, const Tissue&, const FeMesh&>(
            &transferConcentration), py::arg("old_tissue"), py::arg("old_mesh"),
        py::arg("old_field"), py::arg("new_tissue"), py::arg("new_mesh"),
        "interpolate_nodal_field rescaled so that the total amount (integral) is conserved.");
  m.def("transfer_cell_amounts",
        [](const Tissue& old_tissue, const std::vector<double>& old_amounts, const Tissue& new_tissue) {
          CellAmountTransfer r = transferCellAmounts(old_tissue, old_amounts, new_tissue);
          return py::make_tuple(py::array_t<double>(static_cast<py::ssize_t>(r.amounts.size()), r.amounts.data()),
                                r.lost_amount);
        },
        py::arg("old_tissue"), py::arg("old_amounts"), py::arg("new_tissue"),
        "Cell amounts (per old cell slot) shared among the new cells by measure: returns (amounts, lost_amount).");
  m.def("cell_integrals",
        [](const FeMesh& mesh, const Eigen::VectorXd& field, std::size_t cell_slots) {
          if (field.size() != mesh.numNodes())
            throw InputError("cell_integrals: the field has " + std::to_string(field.size()) + " values for " +
                             std::to_string(mesh.numNodes()) + " mesh nodes");
          std::vector<double> v = cellIntegrals(mesh, field, cell_slots);
          return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
        },
        py::arg("mesh"), py::arg("field"), py::arg("cell_slots") = 0, "Integral of a nodal P1 field over each cell.");
}

}  // namespace tessella::python
