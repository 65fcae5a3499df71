// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Selecting wall facets for boundary conditions (by wall id, on the tissue
// boundary or not) and the geometry boundary conditions need from them.

#include "tessella/mesh/fe_mesh.hpp"

#include <Eigen/Core>

#include <vector>

namespace tessella::solvers {

/// Indices of all wall facets on the tissue boundary.
std::vector<int> boundaryFacets(const mesh::FeMesh& mesh);

/// Indices of the wall facets of the given walls (facet_wall in `walls`); with
/// boundary_only, only those on the tissue boundary.
std::vector<int> facetsOfWalls(const mesh::FeMesh& mesh, const std::vector<int>& walls, bool boundary_only = false);

/// Sorted, unique node indices of the given facets.
std::vector<int> facetNodes(const mesh::FeMesh& mesh, const std::vector<int>& facets);

/// The element next to a facet and the local index of its node opposite the facet.
struct FacetSide {
  int element = -1;
  int opposite = -1;
};

/// For each facet, the first element (lowest index) having it as a face.
/// Throws InvalidProblemError if a facet is not a face of any element.
std::vector<FacetSide> facetSides(const mesh::FeMesh& mesh, const std::vector<int>& facets);

/// Unit normal of the facet pointing out of side.element, lying in the plane
/// of that element for triangle meshes (2D: in-plane edge normal).
Eigen::Vector3d outwardNormal(const mesh::FeMesh& mesh, int facet, const FacetSide& side);

}  // namespace tessella::solvers
