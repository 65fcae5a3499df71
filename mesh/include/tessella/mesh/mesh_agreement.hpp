// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How closely a mesh reproduces its tissue: the elements of each cell should
// add up to the cell's area or volume (the meshers mesh the surface the
// geometry measures, docs/meshing.md), and all elements to the tissue's.

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::mesh {

struct MeshAgreement {
  /// Largest |mesh sum - cell measure| / |cell measure| over the tissue's
  /// cells; a NaN (a cell of measure 0, a non-finite node) counts as largest.
  /// 0 for a tissue without cells.
  double worst_cell_difference = 0.0;
  /// The cell with that difference (its index), kInvalidIndex without cells.
  Index worst_cell = kInvalidIndex;
  /// |mesh total - tissue total| / |tissue total|.
  double total_difference = 0.0;
};

/// Compares the element measures of `mesh` (made from `tissue`, elements
/// tagged with cell indices) with the tissue's cell measures.
MeshAgreement meshAgreement(const Tissue& tissue, const FeMesh& mesh);

}  // namespace tessella::mesh
