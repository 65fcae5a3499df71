// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Carrying fields from one tissue mesh to the next after growth and division,
// so that a diffusion run can continue on a dividing tissue.
//
// Cells are matched by lineage: a new cell whose lineage id existed in the old
// tissue comes from that cell; otherwise it comes from its parent (a daughter
// born since the old mesh). Cells of other origin (two divisions in between,
// founders added later) raise InputError naming their lineage ids.

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::mesh {

/// For every cell slot of new_tissue: the slot of the old cell it comes from
/// (by lineage id, then parent id), or -1 for dead slots.
std::vector<int> ancestorCells(const Tissue& old_tissue, const Tissue& new_tissue);

/// The old tissue as the transfer sees it: the lineage id of every cell slot
/// (-1 for dead slots). The overloads below that take it need nothing else
/// of the old tissue, so a caller may keep just this instead of a copy.
std::vector<std::int64_t> cellLineage(const Tissue& tissue);
std::vector<int> ancestorCells(std::span<const std::int64_t> old_lineage, const Tissue& new_tissue);

/// P1 interpolation of a nodal field: each new node is located in the old
/// mesh among the elements of the old cells its own cells come from (the
/// element containing it, or the closest one when growth moved it outside
/// the old cell; it then takes the value at the closest point). A linear
/// field is reproduced exactly wherever the old mesh covers the new node.
Eigen::VectorXd interpolateNodalField(const Tissue& old_tissue, const FeMesh& old_mesh,
                                      const Eigen::VectorXd& old_field, const Tissue& new_tissue,
                                      const FeMesh& new_mesh);

/// Cell-wise amounts (per cell slot of old_tissue) -> per cell slot of
/// new_tissue: every old cell's amount is shared among the new cells it
/// became in proportion to their measures (a dividing cell's substance is
/// conserved). Old cells that left no cell (removed) are reported in
/// `lost_amount`; dead new slots get 0.
struct CellAmountTransfer {
  std::vector<double> amounts;
  double lost_amount = 0.0;
};
CellAmountTransfer transferCellAmounts(const Tissue& old_tissue, std::span<const double> old_amounts,
                                       const Tissue& new_tissue);

/// Integral of a P1 nodal field over each cell of a mesh (exact for P1).
std::vector<double> cellIntegrals(const FeMesh& mesh, const Eigen::VectorXd& field,
                                  std::size_t cell_slots);

/// interpolateNodalField() followed by one global rescaling so that the
/// total amount (integral) of a concentration is the old mesh's: growth then
/// dilutes it instead of creating substance. A continuous P1 field cannot
/// conserve every cell's amount separately (wall nodes are shared); use
/// transferCellAmounts for cell-wise quantities. Where the interpolated total
/// is zero the interpolated values are returned unscaled.
Eigen::VectorXd transferConcentration(const Tissue& old_tissue, const FeMesh& old_mesh,
                                      const Eigen::VectorXd& old_field, const Tissue& new_tissue,
                                      const FeMesh& new_mesh);

/// The same with the old tissue given by cellLineage(): the very same values.
Eigen::VectorXd interpolateNodalField(std::span<const std::int64_t> old_lineage, const FeMesh& old_mesh,
                                      const Eigen::VectorXd& old_field, const Tissue& new_tissue,
                                      const FeMesh& new_mesh);
Eigen::VectorXd transferConcentration(std::span<const std::int64_t> old_lineage, const FeMesh& old_mesh,
                                      const Eigen::VectorXd& old_field, const Tissue& new_tissue,
                                      const FeMesh& new_mesh);

}  // namespace tessella::mesh
