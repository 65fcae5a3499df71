// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/wall_stress.hpp"

#include "tessella/mechanics/wall_state.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

#include <Eigen/Eigenvalues>

namespace tessella::mechanics {

Mat3 cellWallStress(const Tissue& tissue, CellId cell) {
  const auto& tension = tissue.wallProperties().get<double>(kWallTensionName);
  Mat3 sum = Mat3::Zero();
  for (WallId w : tissue.cellWalls(cell)) {
    const auto ends = tissue.topology().edgeVertices(EdgeId(w.index()));
    const Vec3 d = tissue.position(ends[1]) - tissue.position(ends[0]);
    const double length = d.norm();
    if (!(length > 0.0)) continue;
    const double shared = static_cast<double>(tissue.wallCells(w).size());
    sum += (tension[w] * length / shared) * (d / length) * (d / length).transpose();
  }
  return sum / cellMeasure(tissue, cell);
}

void writeCellWallStress(Tissue& tissue) {
  PropertyStore& cells = tissue.cellProperties();
  if (!cells.has(kWallStressName)) cells.add<Sym3>(kWallStressName, Sym3{}, DivisionPolicy::Copy);
  if (!cells.has(kStressDirectionName)) cells.add<Vec3>(kStressDirectionName, Vec3::Zero(), DivisionPolicy::Copy);
  auto& stress = cells.get<Sym3>(kWallStressName);
  auto& direction = cells.get<Vec3>(kStressDirectionName);
  auto& high = cellOutput(tissue, kStressMaxName);
  auto& low = cellOutput(tissue, kStressMinName);
  for (CellId c : tissue.cells()) {
    const Mat3 s = cellWallStress(tissue, c);
    stress[c] = Sym3::fromMatrix(s);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(s.topLeftCorner<2, 2>());
    low[c] = eig.eigenvalues()[0];
    high[c] = eig.eigenvalues()[1];
    direction[c] = Vec3(eig.eigenvectors()(0, 1), eig.eigenvectors()(1, 1), 0.0);
  }
}

}  // namespace tessella::mechanics
