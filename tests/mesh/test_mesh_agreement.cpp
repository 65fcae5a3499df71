// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// meshAgreement: per-cell and total agreement of a mesh's element measures
// with the tissue's cell measures (what `tessella mesh` reports).

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "tessella/mesh/mesh_agreement.hpp"
#include "tessella/mesh/mesh_measures.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/builders.hpp"

using namespace tessella;
using namespace tessella::mesh;

namespace {

// Two unit squares side by side: cells 0 (x in [0, 1]) and 1 (x in [1, 2]).
Tissue twoSquares() {
  const std::vector<Vec3> positions{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  return buildPolygonTissue(positions, {{0, 1, 4, 3}, {1, 2, 5, 4}});
}

// The first element of `cell` in the mesh.
int firstElementOf(const FeMesh& mesh, int cell) {
  for (int e = 0; e < mesh.numElements(); ++e)
    if (mesh.element_cell(e) == cell) return e;
  FAIL("cell " << cell << " has no element");
  return -1;
}

}  // namespace

TEST_CASE("a mesh of a tissue agrees with its cell measures", "[mesh][agreement]") {
  const Tissue tissue = twoSquares();
  const FeMesh mesh = meshTissue(tissue, MeshOptions{.max_edge_length = 0.3});
  const MeshAgreement a = meshAgreement(tissue, mesh);
  CHECK(a.worst_cell_difference < 1e-12);
  CHECK(a.worst_cell < 2);
  CHECK(a.total_difference < 1e-12);
}

TEST_CASE("meshAgreement names the cell whose elements add up worst", "[mesh][agreement]") {
  const Tissue tissue = twoSquares();
  FeMesh mesh = meshTissue(tissue, MeshOptions{.max_edge_length = 0.3});

  SECTION("an element handed to the other cell: both cells off by its area, the total unchanged") {
    const int moved = firstElementOf(mesh, 1);
    const double area = elementMeasure(mesh, moved);
    mesh.element_cell(moved) = 0;
    const MeshAgreement a = meshAgreement(tissue, mesh);
    CHECK(a.worst_cell_difference == Approx(area));  // cells of area 1: relative = absolute
    CHECK(a.worst_cell == 0);                         // a tie goes to the first cell
    CHECK(a.total_difference < 1e-12);
  }
  SECTION("cell 1 stretched by a tenth along x: it is the worst, the total is off by half as much") {
    for (int n = 0; n < mesh.numNodes(); ++n)
      if (mesh.nodes(n, 0) > 1.0) mesh.nodes(n, 0) = 1.0 + 1.1 * (mesh.nodes(n, 0) - 1.0);
    const MeshAgreement a = meshAgreement(tissue, mesh);
    CHECK(a.worst_cell == 1);
    CHECK(a.worst_cell_difference == Approx(0.1));
    CHECK(a.total_difference == Approx(0.05));
  }
  SECTION("a non-finite node makes its cell the worst") {
    int node = -1;  // a node of cell 1 only (clear of the shared wall x = 1)
    for (int n = 0; n < mesh.numNodes() && node < 0; ++n)
      if (mesh.nodes(n, 0) > 1.5) node = n;
    REQUIRE(node >= 0);
    mesh.nodes(node, 1) = std::numeric_limits<double>::quiet_NaN();
    const MeshAgreement a = meshAgreement(tissue, mesh);
    CHECK(a.worst_cell == 1);
    CHECK(std::isnan(a.worst_cell_difference));
    CHECK(std::isnan(a.total_difference));
  }
}
