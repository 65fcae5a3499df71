// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Field transfer across growth and division: P1 interpolation reproduces
// linear fields, cell amounts and concentration totals are conserved.

#include <catch2/catch.hpp>

#include <numeric>

#include "mesh_test_support.hpp"
#include "tessella/mesh/field_transfer.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::test;

namespace {

Eigen::VectorXd linearField(const FeMesh& mesh) {
  Eigen::VectorXd f(mesh.numNodes());
  for (int n = 0; n < mesh.numNodes(); ++n)
    f(n) = 1.0 + 2.0 * mesh.nodes(n, 0) - 3.0 * mesh.nodes(n, 1) + 0.5 * mesh.nodes(n, 2);
  return f;
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace

TEST_CASE("division in 2D: linear fields carried exactly, amounts conserved", "[mesh][transfer]") {
  const Tissue before = rectangularGrid(2, 1);
  const MeshOptions o{.min_angle_degrees = 20, .max_edge_length = 0.2};
  const FeMesh old_mesh = meshTissue(before, o);
  Tissue after = before;
  const CellSplit split = after.splitCell(CellId(0), Plane{Vec3(0.5, 0.5, 0), Vec3(1, 0, 0)});
  const FeMesh new_mesh = meshTissue(after, o);

  const std::vector<int> ancestor = ancestorCells(before, after);
  CHECK(ancestor[0] == 0);
  CHECK(ancestor[split.daughter.index()] == 0);
  CHECK(ancestor[1] == 1);

  const Eigen::VectorXd f_new = interpolateNodalField(before, old_mesh, linearField(old_mesh), after, new_mesh);
  CHECK((f_new - linearField(new_mesh)).cwiseAbs().maxCoeff() < 1e-12);

  const std::vector<double> amounts = {3.0, 5.0};
  const CellAmountTransfer moved = transferCellAmounts(before, amounts, after);
  CHECK(moved.lost_amount == 0.0);
  CHECK(sum(moved.amounts) == Approx(8.0).epsilon(1e-14));
  // Daughters share the mother's amount by area (both halves have area 0.5).
  CHECK(moved.amounts[0] == Approx(1.5).epsilon(1e-12));
  CHECK(moved.amounts[split.daughter.index()] == Approx(1.5).epsilon(1e-12));
  CHECK(moved.amounts[1] == 5.0);
}

TEST_CASE("growth then division in 2D: total concentration amount conserved", "[mesh][transfer]") {
  const Tissue before = rectangularGrid(3, 2);
  const MeshOptions o{.min_angle_degrees = 20, .max_edge_length = 0.25};
  const FeMesh old_mesh = meshTissue(before, o);
  Tissue after = before;
  for (Vec3& p : after.mutablePositions()) p = Vec3(1.3 * p.x() + 0.1 * p.y(), 1.1 * p.y(), 0);  // anisotropic growth
  after.splitCell(CellId(4), Plane{cellCentroid(after, CellId(4)), Vec3(1, 0.2, 0)});
  const FeMesh new_mesh = meshTissue(after, o);

  Eigen::VectorXd c_old(old_mesh.numNodes());
  for (int n = 0; n < old_mesh.numNodes(); ++n) c_old(n) = 1.0 + std::sin(old_mesh.nodes(n, 0)) * old_mesh.nodes(n, 1);
  const Eigen::VectorXd c_new = transferConcentration(before, old_mesh, c_old, after, new_mesh);
  const double old_total = sum(cellIntegrals(old_mesh, c_old, before.cellSlots()));
  const double new_total = sum(cellIntegrals(new_mesh, c_new, after.cellSlots()));
  CHECK(new_total == Approx(old_total).epsilon(1e-12));
  // Growth dilutes: the total area grew by 1.3 * 1.1, so concentrations fell.
  CHECK(c_new.mean() < c_old.mean());

  std::vector<double> amounts(before.cellSlots());
  for (CellId c : before.cells()) amounts[c.index()] = 1.0 + c.index();
  const CellAmountTransfer moved = transferCellAmounts(before, amounts, after);
  CHECK(sum(moved.amounts) == Approx(sum(amounts)).epsilon(1e-14));
}

TEST_CASE("division in 3D: linear fields carried exactly, amounts conserved", "[mesh][transfer]") {
  const Tissue before = boxGrid(2, 1, 1);
  const MeshOptions o{.max_volume = 0.02};
  const FeMesh old_mesh = meshTissue(before, o);
  Tissue after = before;
  const CellSplit split = after.splitCell(CellId(1), Plane{Vec3(1.5, 0.5, 0.5), Vec3(0.2, 1, 0.1)});
  const FeMesh new_mesh = meshTissue(after, o);
  requireMeasuresMatch(after, new_mesh);
  const Eigen::VectorXd f_new = interpolateNodalField(before, old_mesh, linearField(old_mesh), after, new_mesh);
  CHECK((f_new - linearField(new_mesh)).cwiseAbs().maxCoeff() < 1e-11);

  const std::vector<double> amounts = {2.0, 7.0};
  const CellAmountTransfer moved = transferCellAmounts(before, amounts, after);
  CHECK(sum(moved.amounts) == Approx(9.0).epsilon(1e-14));
  CHECK(moved.amounts[1] + moved.amounts[split.daughter.index()] == Approx(7.0).epsilon(1e-14));
  CHECK(moved.amounts[split.daughter.index()] / 7.0 ==
        Approx(cellMeasure(after, split.daughter)).epsilon(1e-12));
}

TEST_CASE("transfer input errors name the values", "[mesh][transfer][errors]") {
  const Tissue t = rectangularGrid(2, 1);
  const FeMesh mesh = meshTissue(t);
  CHECK_THROWS_AS(interpolateNodalField(t, mesh, Eigen::VectorXd::Zero(3), t, mesh), InputError);
  const std::vector<double> wrong = {1.0};
  CHECK_THROWS_AS(transferCellAmounts(t, wrong, t), InputError);
  // A tissue with unrelated lineage cannot be matched.
  const Tissue other = rectangularGrid(5, 1);
  CHECK_THROWS_WITH(transferCellAmounts(t, std::vector<double>{1.0, 2.0}, other), Catch::Contains("lineage id"));
}
