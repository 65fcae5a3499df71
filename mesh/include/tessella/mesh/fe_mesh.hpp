// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// FeMesh: a finite-element mesh as plain Eigen arrays, independent of the cell
// complex. mesh/ produces it from a tissue; solvers/ solve on it and io/ writes
// it. This header alone is the target tessella::fe_mesh (Eigen only), so those
// two link it without the meshers.

#include <Eigen/Core>

namespace tessella::mesh {

template <typename T>
using RowMatrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct FeMesh {
  /// Topological dimension of the elements: 2 (triangles, flat or on a curved
  /// surface) or 3 (tetrahedra).
  int dim = 2;
  /// Node coordinates, one row per node (always 3D).
  RowMatrix<double> nodes;
  /// Element connectivity, one row of dim+1 node indices per element.
  /// Triangles are ordered counter-clockwise w.r.t. their cell's normal;
  /// tetrahedra have positive orientation (det[b-a, c-a, d-a] > 0).
  RowMatrix<int> elements;
  /// Cell (tissue cell index) of each element.
  Eigen::VectorXi element_cell;
  /// Facets lying on tissue walls, one row of dim node indices per facet
  /// (segments in 2D, triangles in 3D): every wall, interior or boundary.
  RowMatrix<int> wall_facets;
  /// Wall (tissue wall index) of each wall facet.
  Eigen::VectorXi facet_wall;
  /// True for wall facets on the tissue boundary (one adjacent element).
  Eigen::Matrix<bool, Eigen::Dynamic, 1> facet_on_boundary;
  /// Tissue vertex index of each node, or -1 where the node was added by the mesher.
  Eigen::VectorXi node_vertex;

  int numNodes() const { return static_cast<int>(nodes.rows()); }
  int numElements() const { return static_cast<int>(elements.rows()); }
  int numWallFacets() const { return static_cast<int>(wall_facets.rows()); }
};

}  // namespace tessella::mesh
