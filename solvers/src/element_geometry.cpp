// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/solvers/element_geometry.hpp"

#include "tessella/solvers/errors.hpp"
#include "tessella/tissue/format.hpp"

#include <Eigen/Geometry>  // cross product
#include <Eigen/LU>

#include <cmath>
#include <sstream>
#include <string>

namespace tessella::solvers {

namespace {

Eigen::Vector3d node(const mesh::FeMesh& mesh, int i) { return mesh.nodes.row(i).transpose(); }

[[noreturn]] void degenerate(int e, double measure) {
  std::ostringstream msg;
  msg << "FE mesh: element " << e << " is degenerate (measure " << formatNumber(measure, 6) << ")";
  throw InvalidProblemError(msg.str());
}

}  // namespace

ElementGeometry elementGeometry(const mesh::FeMesh& mesh, int e) {
  ElementGeometry g;
  const int d = mesh.dim;
  const Eigen::Vector3d x0 = node(mesh, mesh.elements(e, 0));
  double hmax2 = 0.0;  // squared longest edge from x0, the scale for the degeneracy test
  if (d == 2) {
    Eigen::Matrix<double, 3, 2> J;
    J.col(0) = node(mesh, mesh.elements(e, 1)) - x0;
    J.col(1) = node(mesh, mesh.elements(e, 2)) - x0;
    hmax2 = std::max(J.col(0).squaredNorm(), J.col(1).squaredNorm());
    const Eigen::Matrix2d gram = J.transpose() * J;
    const double det = gram.determinant();
    g.measure = det > 0.0 ? 0.5 * std::sqrt(det) : 0.0;
    if (!(g.measure > 1e-13 * hmax2)) degenerate(e, g.measure);
    const Eigen::Matrix<double, 3, 2> G = J * gram.inverse();
    g.gradients.row(1) = G.col(0).transpose();
    g.gradients.row(2) = G.col(1).transpose();
    g.gradients.row(0) = -(g.gradients.row(1) + g.gradients.row(2));
  } else {
    Eigen::Matrix3d J;
    for (int k = 0; k < 3; ++k) {
      J.col(k) = node(mesh, mesh.elements(e, k + 1)) - x0;
      hmax2 = std::max(hmax2, J.col(k).squaredNorm());
    }
    const double det = J.determinant();
    // |det|: the FeMesh contract says positive, but the gradients below are
    // right for either orientation, so do not fail on a flipped tetrahedron.
    g.measure = std::abs(det) / 6.0;
    if (!(g.measure > 1e-13 * hmax2 * std::sqrt(hmax2))) degenerate(e, g.measure);
    const Eigen::Matrix3d G = J.inverse().transpose();  // = J (J^T J)^{-1} for square J
    for (int k = 0; k < 3; ++k) g.gradients.row(k + 1) = G.col(k).transpose();
    g.gradients.row(0) = -(g.gradients.row(1) + g.gradients.row(2) + g.gradients.row(3));
  }
  return g;
}

double simplexMeasure(const mesh::FeMesh& mesh, const int* nodes, int count) {
  const Eigen::Vector3d x0 = node(mesh, nodes[0]);
  if (count == 2) return (node(mesh, nodes[1]) - x0).norm();
  if (count == 3) return 0.5 * (node(mesh, nodes[1]) - x0).cross(node(mesh, nodes[2]) - x0).norm();
  if (count == 4) {
    Eigen::Matrix3d J;
    for (int k = 0; k < 3; ++k) J.col(k) = node(mesh, nodes[k + 1]) - x0;
    return std::abs(J.determinant()) / 6.0;
  }
  throw InvalidProblemError("simplexMeasure: a simplex has 2, 3 or 4 nodes here, got " + std::to_string(count));
}

void checkMesh(const mesh::FeMesh& mesh) {
  std::ostringstream msg;
  msg << "FE mesh: ";
  const int n = mesh.numNodes();
  if (mesh.dim != 2 && mesh.dim != 3) {
    msg << "dim must be 2 or 3, got " << mesh.dim;
  } else if (mesh.nodes.cols() != 3) {
    msg << "nodes must have 3 columns, got " << mesh.nodes.cols();
  } else if (mesh.numElements() > 0 && mesh.elements.cols() != mesh.dim + 1) {
    msg << "elements must have dim+1 = " << mesh.dim + 1 << " columns, got " << mesh.elements.cols();
  } else if (mesh.element_cell.size() != mesh.numElements()) {
    msg << "element_cell has " << mesh.element_cell.size() << " entries for " << mesh.numElements() << " elements";
  } else if (mesh.numElements() > 0 && (mesh.elements.minCoeff() < 0 || mesh.elements.maxCoeff() >= n)) {
    msg << "element node index out of range [0, " << n << ")";
  } else if (mesh.numElements() > 0 && mesh.element_cell.minCoeff() < 0) {
    msg << "negative element_cell entry";
  } else if (mesh.numWallFacets() > 0 && mesh.wall_facets.cols() != mesh.dim) {
    msg << "wall_facets must have dim = " << mesh.dim << " columns, got " << mesh.wall_facets.cols();
  } else if (mesh.numWallFacets() > 0 && (mesh.wall_facets.minCoeff() < 0 || mesh.wall_facets.maxCoeff() >= n)) {
    msg << "wall facet node index out of range [0, " << n << ")";
  } else if (mesh.facet_wall.size() != mesh.numWallFacets()) {
    msg << "facet_wall has " << mesh.facet_wall.size() << " entries for " << mesh.numWallFacets() << " facets";
  } else if (mesh.facet_on_boundary.size() != mesh.numWallFacets()) {
    msg << "facet_on_boundary has " << mesh.facet_on_boundary.size() << " entries for " << mesh.numWallFacets()
        << " facets";
  } else if (!mesh.nodes.allFinite()) {
    msg << "node coordinates are not all finite";
  } else {
    return;
  }
  throw InvalidProblemError(msg.str());
}

int numCells(const mesh::FeMesh& mesh) { return mesh.numElements() > 0 ? mesh.element_cell.maxCoeff() + 1 : 0; }

Eigen::VectorXd cellToElement(const mesh::FeMesh& mesh, const Eigen::VectorXd& per_cell, std::string_view what,
                              bool nonnegative) {
  const int cells = numCells(mesh);
  if (per_cell.size() != 1 && per_cell.size() < cells) {
    std::ostringstream msg;
    msg << what << ": " << per_cell.size() << " per-cell values, but the mesh refers to " << cells
        << " cells (give one value per cell id, or a single uniform value)";
    throw InvalidProblemError(msg.str());
  }
  for (Eigen::Index c = 0; c < per_cell.size(); ++c) {
    const double v = per_cell[c];
    if (!std::isfinite(v) || (nonnegative && v < 0.0)) {
      std::ostringstream msg;
      msg << what << " of cell " << c << " is " << formatNumber(v)
          << (nonnegative ? "; it must be finite and >= 0" : "; it must be finite");
      throw InvalidProblemError(msg.str());
    }
  }
  Eigen::VectorXd out(mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e) out[e] = per_cell.size() == 1 ? per_cell[0] : per_cell[mesh.element_cell[e]];
  return out;
}

}  // namespace tessella::solvers
