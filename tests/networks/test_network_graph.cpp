// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>

#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_graph.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using namespace tessella::networks;

TEST_CASE("networkGraph of a rectangular grid: unit measures, interior walls, normals along the axes", "[networks]") {
  Tissue t = rectangularGrid(3, 2, 2.0, 1.0);
  GeometryCache geometry;
  std::vector<CellId> cells;
  const NetworkGraph g = networkGraph(t, geometry, {}, &cells);
  REQUIRE(g.numCells() == 6);
  REQUIRE(cells.size() == 6);
  for (double m : g.measure) CHECK(m == Approx(2.0));
  // 3x2 cells: 2*2 vertical interior walls (length 1) and 3 horizontal ones (length 2).
  REQUIRE(g.interfaces.size() == 7);
  int vertical = 0, horizontal = 0;
  for (const NetworkInterface& f : g.interfaces) {
    const Vec3 d = g.centroid[f.cell_j] - g.centroid[f.cell_i];
    CHECK(f.normal.dot(d.normalized()) == Approx(1.0));
    if (std::abs(d.x()) > 0.5) {
      ++vertical;
      CHECK(f.measure == Approx(1.0));
    } else {
      ++horizontal;
      CHECK(f.measure == Approx(2.0));
    }
  }
  CHECK(vertical == 4);
  CHECK(horizontal == 3);
  REQUIRE_THROWS_WITH(networkGraph(t, geometry, {"missing"}), Catch::Contains("'missing'"));
}
