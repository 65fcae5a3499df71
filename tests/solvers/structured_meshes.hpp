// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Structured FeMesh fixtures for the solver tests: a rectangle split into
// triangles, a box split into tetrahedra (6 per cube, Kuhn subdivision), and a
// strip of a cylinder (a curved triangle sheet in R^3).
//
// Walls: rectangle 0: x=0, 1: x=lx, 2: y=0, 3: y=ly; box adds 4: z=0, 5: z=lz;
// cylinder strip 0: theta=0, 1: theta=angle, 2: z=0, 3: z=height. With
// two_cells, elements with centroid x < lx/2 are cell 0, the rest cell 1, and
// the interior wall x = lx/2 has id 6 (box) / 4 (rectangle), not on the boundary.

#include "tessella/mesh/fe_mesh.hpp"

#include <Eigen/Core>

#include <vector>

namespace tessella::test {

mesh::FeMesh rectangleMesh(int nx, int ny, double lx = 1.0, double ly = 1.0, bool two_cells = false);
mesh::FeMesh boxMesh(int nx, int ny, int nz, double lx = 1.0, double ly = 1.0, double lz = 1.0, bool two_cells = false);
mesh::FeMesh cylinderStrip(int n_theta, int n_z, double radius, double angle, double height);

/// Moves interior nodes (not on the box/rectangle boundary) by up to
/// `fraction` of the spacing h, pseudo-randomly but reproducibly.
void perturbInterior(mesh::FeMesh& mesh, double h, double fraction, unsigned seed = 12345);

/// Nodes of the given wall ids (from wall_facets).
std::vector<int> nodesOfWalls(const mesh::FeMesh& mesh, const std::vector<int>& walls);

/// Squared L2 error and squared H1-seminorm error of the P1 field uh against
/// u / grad u, with a collapsed Gauss rule exact to degree 5 on each simplex.
struct ErrorNorms {
  double l2 = 0.0;
  double h1 = 0.0;
};
template <typename U, typename GradU>
ErrorNorms errorNorms(const mesh::FeMesh& mesh, const Eigen::VectorXd& uh, U&& u, GradU&& grad_u);

/// Quadrature on the reference simplex of dimension d: points (barycentric
/// coordinates of nodes 1..d) and weights summing to 1 (normalised volume).
struct Quadrature {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
};
Quadrature simplexQuadrature(int dim);

}  // namespace tessella::test

#include "structured_meshes_impl.hpp"
