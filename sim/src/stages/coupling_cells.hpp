// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What the solver stages read off the tissue and the mesh: per-cell
// coefficients by cell type, source/polar cell marks, and the wall facets of
// a boundary region.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/sim/stages/coupling_stages.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::sim::detail {

/// One value per cell slot: the coefficient of each live cell's type (the
/// integer cell property `type_property`; InputError naming the section when
/// it is missing or not an integer column).
Eigen::VectorXd perCell(const Tissue& tissue, const CellCoefficient& k, const std::string& type_property,
                        const std::string& section);

/// Adds the int64 cell property `name` (copied at division) when absent and
/// sets it to 1 on the cells listed by lineage id and, with radius > 0, on
/// the cells whose centroid lies within radius of center. Unknown lineage ids
/// are an InputError naming `what`.
void markCells(Tissue& tissue, const std::string& name, const std::vector<std::int64_t>& lineage_ids,
               const Vec3& center, double radius, const std::string& what);

/// The cells marked 1 in the int64 property `name` (false everywhere when absent).
std::vector<bool> marked(const Tissue& tissue, const std::string& name);

/// Wall facets of a boundary region; InputError naming `what` when it holds none.
std::vector<int> regionFacets(const mesh::FeMesh& mesh, BoundaryRegion region, const std::string& what);

/// The double cell property `name` (created with `policy` when absent).
PropertyColumn<double>& doubleColumn(Tissue& tissue, const std::string& name, DivisionPolicy policy);

}  // namespace tessella::sim::detail
