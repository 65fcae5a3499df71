// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The conformity checker itself must catch broken meshes, or the mesher tests
// that rely on it prove nothing.

#include <catch2/catch.hpp>

#include "mesh_test_support.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::mesh;

TEST_CASE("checkConformity detects hanging nodes, holes and untagged walls", "[mesh][conformity]") {
  const Tissue t = rectangularGrid(2, 2);
  const FeMesh good = meshTissue(t, MeshOptions{.max_edge_length = 0.3});
  REQUIRE(checkConformity(good).ok);

  SECTION("a missing element leaves a hole") {
    FeMesh bad = good;
    bad.elements.conservativeResize(bad.numElements() - 1, 3);
    bad.element_cell.conservativeResize(bad.numElements());
    CHECK_FALSE(checkConformity(bad).ok);
  }
  SECTION("an element tagged with the wrong cell crosses no wall") {
    FeMesh bad = good;
    // Retag an element that touches no wall, so its facets now separate cells
    // without being wall facets.
    for (int e = 0; e < bad.numElements(); ++e) {
      bool on_wall = false;
      for (int k = 0; k < 3; ++k)
        for (int f = 0; f < bad.numWallFacets(); ++f)
          on_wall = on_wall || bad.wall_facets(f, 0) == bad.elements(e, k) || bad.wall_facets(f, 1) == bad.elements(e, k);
      if (!on_wall) {
        bad.element_cell(e) = (bad.element_cell(e) + 1) % 4;
        break;
      }
    }
    const auto r = checkConformity(bad);
    CHECK_FALSE(r.ok);
    CHECK_THAT(r.message, Catch::Contains("not a wall facet"));
  }
  SECTION("a split element makes a hanging node") {
    FeMesh bad = good;
    // Split element 0 at the midpoint of its edge 0-1 without splitting the neighbour.
    const int a = bad.elements(0, 0), b = bad.elements(0, 1), c = bad.elements(0, 2);
    const int m = bad.numNodes();
    bad.nodes.conservativeResize(m + 1, 3);
    bad.nodes.row(m) = 0.5 * (bad.nodes.row(a) + bad.nodes.row(b));
    bad.node_vertex.conservativeResize(m + 1);
    bad.node_vertex(m) = -1;
    bad.elements.row(0) << a, m, c;
    const int n = bad.numElements();
    bad.elements.conservativeResize(n + 1, 3);
    bad.elements.row(n) << m, b, c;
    bad.element_cell.conservativeResize(n + 1);
    bad.element_cell(n) = bad.element_cell(0);
    CHECK_FALSE(checkConformity(bad).ok);
  }
  SECTION("a wall facet marked boundary inside the tissue") {
    FeMesh bad = good;
    for (int f = 0; f < bad.numWallFacets(); ++f)
      if (!bad.facet_on_boundary(f)) {
        bad.facet_on_boundary(f) = true;
        break;
      }
    CHECK_FALSE(checkConformity(bad).ok);
  }
}
