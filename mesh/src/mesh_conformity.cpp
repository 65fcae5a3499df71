// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mesh/mesh_conformity.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "tessella/mesh/mesh_measures.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::mesh {
namespace {

using FacetKey = std::array<int, 3>;  // sorted node ids (third = -1 for segments)

FacetKey keyOf(std::array<int, 3> ids, int n) {
  if (n == 2) ids[2] = -1;
  std::sort(ids.begin(), ids.begin() + n);
  return ids;
}

std::string facetText(const FacetKey& k) {
  std::string s = "{" + std::to_string(k[0]) + ", " + std::to_string(k[1]);
  if (k[2] >= 0) s += ", " + std::to_string(k[2]);
  return s + "}";
}

}  // namespace

ConformityReport checkConformity(const FeMesh& m) {
  ConformityReport r;
  const auto fail = [&](const std::string& msg) {
    r.ok = false;
    r.message = msg;
    return r;
  };
  const int corners = m.dim + 1;
  if (m.elements.cols() != corners) return fail("elements have " + std::to_string(m.elements.cols()) + " columns");
  if (m.element_cell.size() != m.elements.rows()) return fail("element_cell has the wrong size");
  if (m.node_vertex.size() != m.nodes.rows()) return fail("node_vertex has the wrong size");
  if (m.facet_wall.size() != m.wall_facets.rows() || m.facet_on_boundary.size() != m.wall_facets.rows())
    return fail("facet_wall / facet_on_boundary have the wrong size");

  struct Use {
    int count = 0;
    int element[2] = {-1, -1};
  };
  std::map<FacetKey, Use> uses;
  for (int e = 0; e < m.numElements(); ++e) {
    if (m.element_cell(e) < 0) return fail("element " + std::to_string(e) + " has no cell");
    for (int k = 0; k < corners; ++k)
      if (m.elements(e, k) < 0 || m.elements(e, k) >= m.numNodes())
        return fail("element " + std::to_string(e) + " has a bad node index " + std::to_string(m.elements(e, k)));
    if (m.dim == 3 && !(signedTetVolume(m, e) > 0.0))
      return fail("tetrahedron " + std::to_string(e) + " is not positively oriented (volume " +
                  formatNumber(signedTetVolume(m, e), 6) + ")");
    if (m.dim == 2 && !(elementMeasure(m, e) > 0.0)) return fail("triangle " + std::to_string(e) + " is degenerate");
    for (int skip = 0; skip < corners; ++skip) {
      std::array<int, 3> ids{-1, -1, -1};
      int n = 0;
      for (int k = 0; k < corners; ++k)
        if (k != skip) ids[static_cast<std::size_t>(n++)] = m.elements(e, k);
      Use& u = uses[keyOf(ids, m.dim)];
      if (u.count >= 2)
        return fail("facet " + facetText(keyOf(ids, m.dim)) + " is shared by more than two elements (" +
                    std::to_string(u.element[0]) + ", " + std::to_string(u.element[1]) + ", " + std::to_string(e) + ")");
      u.element[u.count++] = e;
    }
  }
  std::map<FacetKey, int> wall_facet;
  for (int f = 0; f < m.numWallFacets(); ++f) {
    std::array<int, 3> ids{m.wall_facets(f, 0), m.wall_facets(f, 1), m.dim == 3 ? m.wall_facets(f, 2) : -1};
    const FacetKey key = keyOf(ids, m.dim);
    if (!wall_facet.emplace(key, f).second) return fail("wall facet " + facetText(key) + " is listed twice");
    const auto it = uses.find(key);
    if (it == uses.end())
      return fail("wall facet " + std::to_string(f) + " " + facetText(key) + " of wall " +
                  std::to_string(m.facet_wall(f)) + " is not a facet of any element (a hanging wall node)");
    const Use& u = it->second;
    if (m.facet_on_boundary(f) && u.count != 1)
      return fail("boundary wall facet " + std::to_string(f) + " of wall " + std::to_string(m.facet_wall(f)) +
                  " has " + std::to_string(u.count) + " elements");
    if (!m.facet_on_boundary(f)) {
      if (u.count != 2)
        return fail("interior wall facet " + std::to_string(f) + " of wall " + std::to_string(m.facet_wall(f)) +
                    " has " + std::to_string(u.count) + " element(s): the cells do not share its nodes");
      if (m.element_cell(u.element[0]) == m.element_cell(u.element[1]))
        return fail("interior wall facet " + std::to_string(f) + " of wall " + std::to_string(m.facet_wall(f)) +
                    " has the same cell " + std::to_string(m.element_cell(u.element[0])) + " on both sides");
    }
  }
  for (const auto& [key, u] : uses) {
    if (u.count == 2) {
      ++r.interior_facets;
      if (m.element_cell(u.element[0]) != m.element_cell(u.element[1]) && !wall_facet.count(key))
        return fail("facet " + facetText(key) + " between elements " + std::to_string(u.element[0]) + " (cell " +
                    std::to_string(m.element_cell(u.element[0])) + ") and " + std::to_string(u.element[1]) +
                    " (cell " + std::to_string(m.element_cell(u.element[1])) + ") is not a wall facet");
    } else {
      ++r.boundary_facets;
      if (!wall_facet.count(key))
        return fail("facet " + facetText(key) + " of element " + std::to_string(u.element[0]) +
                    " has no neighbour and lies on no wall (a hanging node or a hole)");
    }
  }
  return r;
}

}  // namespace tessella::mesh
