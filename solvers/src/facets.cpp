// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/solvers/facets.hpp"

#include "tessella/solvers/element_geometry.hpp"
#include "tessella/solvers/errors.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace tessella::solvers {

std::vector<int> boundaryFacets(const mesh::FeMesh& mesh) {
  checkMesh(mesh);
  std::vector<int> out;
  for (int f = 0; f < mesh.numWallFacets(); ++f)
    if (mesh.facet_on_boundary[f]) out.push_back(f);
  return out;
}

std::vector<int> facetsOfWalls(const mesh::FeMesh& mesh, const std::vector<int>& walls, bool boundary_only) {
  checkMesh(mesh);
  const std::set<int> wanted(walls.begin(), walls.end());
  std::vector<int> out;
  for (int f = 0; f < mesh.numWallFacets(); ++f)
    if (wanted.count(mesh.facet_wall[f]) && (!boundary_only || mesh.facet_on_boundary[f])) out.push_back(f);
  return out;
}

std::vector<int> facetNodes(const mesh::FeMesh& mesh, const std::vector<int>& facets) {
  std::vector<int> nodes;
  for (int f : facets) {
    if (f < 0 || f >= mesh.numWallFacets())
      throw InvalidProblemError("facet index " + std::to_string(f) + " out of range");
    for (int a = 0; a < mesh.dim; ++a) nodes.push_back(mesh.wall_facets(f, a));
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::vector<FacetSide> facetSides(const mesh::FeMesh& mesh, const std::vector<int>& facets) {
  checkMesh(mesh);
  const int d = mesh.dim;
  using Key = std::array<int, 3>;
  auto key = [d](const int* nodes) {
    // Sorted node triple (-1 padded in 2D): a facet's identity regardless of order.
    Key k{nodes[0], nodes[1], d == 3 ? nodes[2] : -1};
    if (k[0] > k[1]) std::swap(k[0], k[1]);
    if (d == 3) {
      if (k[1] > k[2]) std::swap(k[1], k[2]);
      if (k[0] > k[1]) std::swap(k[0], k[1]);
    }
    return k;
  };
  // Only the requested facets are indexed, then every element face is looked up once.
  std::map<Key, std::vector<std::size_t>> wanted;
  for (std::size_t i = 0; i < facets.size(); ++i) {
    const int f = facets[i];
    if (f < 0 || f >= mesh.numWallFacets()) throw InvalidProblemError("facet index " + std::to_string(f) + " out of range");
    wanted[key(&mesh.wall_facets(f, 0))].push_back(i);
  }
  std::vector<FacetSide> sides(facets.size());
  for (int e = 0; e < mesh.numElements(); ++e) {
    for (int opp = 0; opp <= d; ++opp) {
      int face[3];
      int k = 0;
      for (int a = 0; a <= d; ++a)
        if (a != opp) face[k++] = mesh.elements(e, a);
      const auto it = wanted.find(key(face));
      if (it == wanted.end()) continue;
      for (std::size_t i : it->second)
        if (sides[i].element < 0) sides[i] = FacetSide{e, opp};
    }
  }
  for (std::size_t i = 0; i < facets.size(); ++i)
    if (sides[i].element < 0)
      throw InvalidProblemError("wall facet " + std::to_string(facets[i]) + " is not a face of any element");
  return sides;
}

Eigen::Vector3d outwardNormal(const mesh::FeMesh& mesh, int facet, const FacetSide& side) {
  const int d = mesh.dim;
  const Eigen::Vector3d opposite = mesh.nodes.row(mesh.elements(side.element, side.opposite)).transpose();
  const Eigen::Vector3d p0 = mesh.nodes.row(mesh.wall_facets(facet, 0)).transpose();
  // Direction from the opposite node to the facet, minus its components along
  // the facet: what is left is normal to the facet (and, for a triangle, in
  // the triangle's plane) and points outwards.
  Eigen::Vector3d v = p0 - opposite;
  Eigen::Matrix<double, 3, 2> T = Eigen::Matrix<double, 3, 2>::Zero();
  for (int a = 1; a < d; ++a) T.col(a - 1) = mesh.nodes.row(mesh.wall_facets(facet, a)).transpose() - p0;
  const auto Td = T.leftCols(d - 1);
  const Eigen::MatrixXd gram = Td.transpose() * Td;
  v -= Td * gram.ldlt().solve(Td.transpose() * v);
  const double len = v.norm();
  if (!(len > 0.0)) throw InvalidProblemError("outwardNormal: degenerate facet " + std::to_string(facet));
  return v / len;
}

}  // namespace tessella::solvers
