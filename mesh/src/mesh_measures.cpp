// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mesh/mesh_measures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

namespace tessella::mesh {
namespace {

Eigen::Vector3d node(const FeMesh& m, int i) { return m.nodes.row(i).transpose(); }
Eigen::Vector3d corner(const FeMesh& m, int e, int k) { return node(m, m.elements(e, k)); }

}  // namespace

double signedTetVolume(const FeMesh& m, int e) {
  const Eigen::Vector3d a = corner(m, e, 0);
  return (corner(m, e, 1) - a).dot((corner(m, e, 2) - a).cross(corner(m, e, 3) - a)) / 6.0;
}

double elementMeasure(const FeMesh& m, int e) {
  if (m.dim == 3) return std::abs(signedTetVolume(m, e));
  const Eigen::Vector3d a = corner(m, e, 0);
  return 0.5 * (corner(m, e, 1) - a).cross(corner(m, e, 2) - a).norm();
}

std::vector<double> cellMeasuresOfMesh(const FeMesh& m, std::size_t cell_slots) {
  std::size_t n = cell_slots;
  for (int e = 0; e < m.numElements(); ++e) n = std::max(n, static_cast<std::size_t>(m.element_cell(e)) + 1);
  std::vector<double> out(n, 0.0);
  for (int e = 0; e < m.numElements(); ++e) out[static_cast<std::size_t>(m.element_cell(e))] += elementMeasure(m, e);
  return out;
}

double totalMeasureOfMesh(const FeMesh& m) {
  double sum = 0.0;
  for (int e = 0; e < m.numElements(); ++e) sum += elementMeasure(m, e);
  return sum;
}

double triangleMinAngleDegrees(const FeMesh& m, int e) {
  double smallest = 180.0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d a = corner(m, e, k), b = corner(m, e, (k + 1) % 3), c = corner(m, e, (k + 2) % 3);
    const Eigen::Vector3d u = b - a, v = c - a;
    const double angle = std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / std::numbers::pi;
    smallest = std::min(smallest, angle);
  }
  return smallest;
}

double tetRadiusEdgeRatio(const FeMesh& m, int e) {
  const Eigen::Vector3d a = corner(m, e, 0);
  Eigen::Matrix3d A;
  Eigen::Vector3d rhs;
  for (int k = 1; k < 4; ++k) {
    const Eigen::Vector3d d = corner(m, e, k) - a;
    A.row(k - 1) = d.transpose();
    rhs(k - 1) = 0.5 * d.squaredNorm();
  }
  const double radius = A.partialPivLu().solve(rhs).norm();  // circumcentre relative to a
  double shortest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) shortest = std::min(shortest, (corner(m, e, i) - corner(m, e, j)).norm());
  return radius / shortest;
}

double wallFacetMeasure(const FeMesh& m, int f) {
  const Eigen::Vector3d a = node(m, m.wall_facets(f, 0));
  if (m.dim == 2) return (node(m, m.wall_facets(f, 1)) - a).norm();
  return 0.5 * (node(m, m.wall_facets(f, 1)) - a).cross(node(m, m.wall_facets(f, 2)) - a).norm();
}

}  // namespace tessella::mesh
