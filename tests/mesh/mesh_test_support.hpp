// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Shared checks of the mesh tests: the invariants every tissue mesh must meet,
// compared with the tissue's own measures (never with numbers from a run).

#include <catch2/catch.hpp>

#include <cmath>
#include <Eigen/Geometry>
#include <map>
#include <vector>

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/mesh/mesh_conformity.hpp"
#include "tessella/mesh/mesh_measures.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::test {

inline bool relativelyClose(double a, double b, double rel = 1e-9) {
  return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b));
}

/// Every element tagged with a live cell; per-cell and total measures equal
/// the tissue's to 1e-9 relative; every live cell has elements.
inline void requireMeasuresMatch(const Tissue& t, const mesh::FeMesh& mesh) {
  REQUIRE(mesh.numElements() > 0);
  for (int e = 0; e < mesh.numElements(); ++e) {
    const int c = mesh.element_cell(e);
    REQUIRE(c >= 0);
    REQUIRE(static_cast<std::size_t>(c) < t.cellSlots());
    REQUIRE(t.alive(CellId(static_cast<Index>(c))));
  }
  const auto sums = mesh::cellMeasuresOfMesh(mesh, t.cellSlots());
  for (CellId c : t.cells()) {
    INFO("cell " << c.index() << ": mesh " << sums[c.index()] << " tissue " << cellMeasure(t, c));
    CHECK(relativelyClose(sums[c.index()], cellMeasure(t, c)));
  }
  CHECK(relativelyClose(mesh::totalMeasureOfMesh(mesh), totalMeasure(t)));
}

/// No hanging nodes; walls are unions of element facets shared by their cells.
inline void requireConforming(const mesh::FeMesh& mesh) {
  const mesh::ConformityReport r = mesh::checkConformity(mesh);
  INFO(r.message);
  REQUIRE(r.ok);
}

/// The wall facets of each wall add up to the wall's length or area, carry
/// the wall's boundary flag, and each tissue vertex is a node at its place.
inline void requireWallsMatch(const Tissue& t, const mesh::FeMesh& mesh) {
  std::vector<double> sums(t.slots(t.wallDegree()), 0.0);
  for (int f = 0; f < mesh.numWallFacets(); ++f) {
    const WallId w(static_cast<Index>(mesh.facet_wall(f)));
    REQUIRE(t.alive(w));
    CHECK(mesh.facet_on_boundary(f) == t.isBoundaryWall(w));
    sums[w.index()] += mesh::wallFacetMeasure(mesh, f);
  }
  for (WallId w : t.walls()) {
    INFO("wall " << w.index());
    CHECK(relativelyClose(sums[w.index()], wallMeasure(t, w)));
  }
  std::vector<int> seen(t.slots(0), 0);
  for (int n = 0; n < mesh.numNodes(); ++n) {
    const int v = mesh.node_vertex(n);
    if (v < 0) continue;
    ++seen[static_cast<std::size_t>(v)];
    CHECK((mesh.nodes.row(n).transpose() - t.position(VertexId(static_cast<Index>(v)))).norm() == 0.0);
  }
  for (VertexId v : t.vertices()) CHECK(seen[v.index()] == 1);
}

/// Measures, conformity and walls: what every mesh of a tissue must satisfy.
inline void requireGoodMesh(const Tissue& t, const mesh::FeMesh& mesh) {
  requireMeasuresMatch(t, mesh);
  requireConforming(mesh);
  requireWallsMatch(t, mesh);
}

}  // namespace tessella::test
