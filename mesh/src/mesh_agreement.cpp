// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mesh/mesh_agreement.hpp"

#include <cmath>
#include <vector>

#include "tessella/mesh/mesh_measures.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::mesh {

MeshAgreement meshAgreement(const Tissue& tissue, const FeMesh& mesh) {
  MeshAgreement agreement;
  const std::vector<double> sums = cellMeasuresOfMesh(mesh, tissue.slots(tissue.dim()));
  bool first = true;
  for (CellId c : tissue.cells()) {
    const double measure = cellMeasure(tissue, c);
    const double difference = std::abs(sums[c.index()] - measure) / std::abs(measure);
    if (first || !(difference <= agreement.worst_cell_difference)) {  // NaN counts as worst
      agreement.worst_cell_difference = difference;
      agreement.worst_cell = c.index();
      first = false;
    }
  }
  const double total = totalMeasure(tissue);
  agreement.total_difference = std::abs(totalMeasureOfMesh(mesh) - total) / std::abs(total);
  return agreement;
}

}  // namespace tessella::mesh
