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

TEST_CASE("networkGraph reads double and int cell properties as numbers, and refuses others", "[networks]") {
  Tissue t = rectangularGrid(2, 2, 1.0, 1.0);
  auto& q = t.cellProperties().add<double>("q", 0.0, DivisionPolicy::Copy);
  auto& label = t.cellProperties().add<int>("label", 0, DivisionPolicy::Copy);
  t.cellProperties().add<Vec3>("v", Vec3::Zero(), DivisionPolicy::Copy);
  std::vector<CellId> cells(t.cells().begin(), t.cells().end());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    q[cells[k]] = 0.5 * static_cast<double>(k);
    label[cells[k]] = 3 - static_cast<int>(k);
  }
  GeometryCache geometry;
  std::vector<CellId> order;
  const NetworkGraph g = networkGraph(t, geometry, {"q", "label"}, &order);
  REQUIRE(order.size() == cells.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    CHECK(g.properties.at("q")[k] == q[order[k]]);
    CHECK(g.properties.at("label")[k] == static_cast<double>(label[order[k]]));
  }
  REQUIRE_THROWS_WITH(networkGraph(t, geometry, {"v"}), Catch::Contains("'v' does not hold numbers"));
}
