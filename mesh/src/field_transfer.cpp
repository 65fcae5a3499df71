// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mesh/field_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include <Eigen/Dense>

#include "closest_point.hpp"
#include "tessella/mesh/mesh_measures.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::mesh {
namespace {


/// Barycentric coordinates of q (assumed in the element's span) in element e.
Eigen::Vector4d barycentric(const FeMesh& m, int e, const Vec3& q) {
  const Vec3 a = m.nodes.row(m.elements(e, 0)).transpose();
  Eigen::Vector4d l = Eigen::Vector4d::Zero();
  if (m.dim == 3) {
    Mat3 A;
    for (int k = 1; k < 4; ++k) A.col(k - 1) = m.nodes.row(m.elements(e, k)).transpose() - a;
    const Vec3 x = A.partialPivLu().solve(q - a);
    l << 1 - x.sum(), x(0), x(1), x(2);
  } else {
    const Vec3 u = Vec3(m.nodes.row(m.elements(e, 1)).transpose()) - a;
    const Vec3 v = Vec3(m.nodes.row(m.elements(e, 2)).transpose()) - a;
    const Vec3 w = q - a;
    const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), wu = w.dot(u), wv = w.dot(v);
    const double det = uu * vv - uv * uv;
    const double s = (vv * wu - uv * wv) / det, r = (uu * wv - uv * wu) / det;
    l << 1 - s - r, s, r, 0;
  }
  return l;
}

/// Distance from p to element e and the barycentric coordinates of the closest point.
double locate(const FeMesh& m, int e, const Vec3& p, Eigen::Vector4d& lambda) {
  const auto corner = [&](int k) { return Vec3(m.nodes.row(m.elements(e, k)).transpose()); };
  if (m.dim == 3) {
    lambda = barycentric(m, e, p);
    if (lambda.minCoeff() >= -1e-12) return 0.0;
    double best = std::numeric_limits<double>::infinity();
    Vec3 best_q;
    for (int skip = 0; skip < 4; ++skip) {
      const int i = (skip + 1) % 4, j = (skip + 2) % 4, k = (skip + 3) % 4;
      const Vec3 q = detail::closestPointOnTriangle(p, corner(i), corner(j), corner(k));
      if ((q - p).norm() < best) best = (q - p).norm(), best_q = q;
    }
    lambda = barycentric(m, e, best_q);
    return best;
  }
  const Vec3 q = detail::closestPointOnTriangle(p, corner(0), corner(1), corner(2));
  lambda = barycentric(m, e, q);
  return (q - p).norm();
}

}  // namespace

std::vector<std::int64_t> cellLineage(const Tissue& tissue) {
  std::vector<std::int64_t> lineage(tissue.cellSlots(), -1);
  for (CellId c : tissue.cells()) lineage[c.index()] = tissue.lineageId(c);
  return lineage;
}

std::vector<int> ancestorCells(const Tissue& old_tissue, const Tissue& new_tissue) {
  return ancestorCells(cellLineage(old_tissue), new_tissue);
}

std::vector<int> ancestorCells(std::span<const std::int64_t> old_lineage, const Tissue& new_tissue) {
  std::unordered_map<std::int64_t, int> by_lineage;
  for (std::size_t c = 0; c < old_lineage.size(); ++c)
    if (old_lineage[c] >= 0) by_lineage[old_lineage[c]] = static_cast<int>(c);
  std::vector<int> out(new_tissue.cellSlots(), -1);
  for (CellId c : new_tissue.cells()) {
    if (auto it = by_lineage.find(new_tissue.lineageId(c)); it != by_lineage.end()) {
      out[c.index()] = it->second;
    } else if (auto jt = by_lineage.find(new_tissue.parentId(c)); jt != by_lineage.end()) {
      out[c.index()] = jt->second;
    } else {
      throw InputError("field transfer: new cell " + std::to_string(c.index()) + " (lineage id " +
                       std::to_string(new_tissue.lineageId(c)) + ", parent id " +
                       std::to_string(new_tissue.parentId(c)) +
                       ") descends from no cell of the old tissue: transfer fields after every division step");
    }
  }
  return out;
}

Eigen::VectorXd interpolateNodalField(const Tissue& old_tissue, const FeMesh& old_mesh, const Eigen::VectorXd& old_field,
                                      const Tissue& new_tissue, const FeMesh& new_mesh) {
  return interpolateNodalField(cellLineage(old_tissue), old_mesh, old_field, new_tissue, new_mesh);
}

Eigen::VectorXd interpolateNodalField(std::span<const std::int64_t> old_lineage, const FeMesh& old_mesh,
                                      const Eigen::VectorXd& old_field, const Tissue& new_tissue,
                                      const FeMesh& new_mesh) {
  if (old_field.size() != old_mesh.numNodes())
    throw InputError("field transfer: the old field has " + std::to_string(old_field.size()) + " values for " +
                     std::to_string(old_mesh.numNodes()) + " nodes");
  if (old_mesh.dim != new_mesh.dim)
    throw InputError("field transfer: the meshes have different dimensions (" + std::to_string(old_mesh.dim) +
                     " and " + std::to_string(new_mesh.dim) + ")");
  const std::vector<int> ancestor = ancestorCells(old_lineage, new_tissue);
  std::vector<std::vector<int>> old_elements(old_lineage.size());
  for (int e = 0; e < old_mesh.numElements(); ++e) {
    const int cell = old_mesh.element_cell(e);
    if (cell < 0 || static_cast<std::size_t>(cell) >= old_lineage.size())
      throw InputError("field transfer: element " + std::to_string(e) + " of the old mesh lies in cell " +
                       std::to_string(cell) + ", but the old tissue has " + std::to_string(old_lineage.size()) +
                       " cell slots");
    old_elements[static_cast<std::size_t>(cell)].push_back(e);
  }
  // The old cells each new node may come from: the ancestors of its cells.
  std::vector<std::vector<int>> node_sources(static_cast<std::size_t>(new_mesh.numNodes()));
  for (int e = 0; e < new_mesh.numElements(); ++e) {
    const int source = ancestor[static_cast<std::size_t>(new_mesh.element_cell(e))];
    for (int k = 0; k <= new_mesh.dim; ++k) {
      auto& s = node_sources[static_cast<std::size_t>(new_mesh.elements(e, k))];
      if (std::find(s.begin(), s.end(), source) == s.end()) s.push_back(source);
    }
  }
  Eigen::VectorXd out(new_mesh.numNodes());
  for (int n = 0; n < new_mesh.numNodes(); ++n) {
    const Vec3 p = new_mesh.nodes.row(n).transpose();
    double best = std::numeric_limits<double>::infinity();
    double value = 0.0;
    for (int cell : node_sources[static_cast<std::size_t>(n)]) {
      for (int e : old_elements[static_cast<std::size_t>(cell)]) {
        Eigen::Vector4d lambda;
        const double d = locate(old_mesh, e, p, lambda);
        if (d < best) {
          best = d;
          value = 0.0;
          for (int k = 0; k <= old_mesh.dim; ++k) value += lambda(k) * old_field(old_mesh.elements(e, k));
        }
        if (best == 0.0) break;
      }
      if (best == 0.0) break;
    }
    if (!std::isfinite(best))
      throw InputError("field transfer: node " + std::to_string(n) + " of the new mesh lies in no element or in a cell with no old elements");
    out(n) = value;
  }
  return out;
}

CellAmountTransfer transferCellAmounts(const Tissue& old_tissue, std::span<const double> old_amounts,
                                       const Tissue& new_tissue) {
  if (old_amounts.size() != old_tissue.cellSlots())
    throw InputError("field transfer: " + std::to_string(old_amounts.size()) + " cell amounts for " +
                     std::to_string(old_tissue.cellSlots()) + " cell slots of the old tissue");
  const std::vector<int> ancestor = ancestorCells(old_tissue, new_tissue);
  std::vector<double> group_measure(old_tissue.cellSlots(), 0.0);
  std::vector<double> measure(new_tissue.cellSlots(), 0.0);
  for (CellId c : new_tissue.cells()) {
    measure[c.index()] = cellMeasure(new_tissue, c);
    group_measure[static_cast<std::size_t>(ancestor[c.index()])] += measure[c.index()];
  }
  CellAmountTransfer out;
  out.amounts.assign(new_tissue.cellSlots(), 0.0);
  for (CellId c : new_tissue.cells()) {
    const auto a = static_cast<std::size_t>(ancestor[c.index()]);
    out.amounts[c.index()] = old_amounts[a] * (measure[c.index()] / group_measure[a]);
  }
  for (CellId c : old_tissue.cells())
    if (group_measure[c.index()] == 0.0) out.lost_amount += old_amounts[c.index()];
  return out;
}

std::vector<double> cellIntegrals(const FeMesh& mesh, const Eigen::VectorXd& field, std::size_t cell_slots) {
  std::vector<double> out(cell_slots, 0.0);
  for (int e = 0; e < mesh.numElements(); ++e) {
    double mean = 0.0;
    for (int k = 0; k <= mesh.dim; ++k) mean += field(mesh.elements(e, k));
    mean /= mesh.dim + 1;  // exact integral of a P1 field: measure times the mean of the corner values
    const auto c = static_cast<std::size_t>(mesh.element_cell(e));
    if (c >= out.size()) out.resize(c + 1, 0.0);
    out[c] += elementMeasure(mesh, e) * mean;
  }
  return out;
}

Eigen::VectorXd transferConcentration(const Tissue& old_tissue, const FeMesh& old_mesh, const Eigen::VectorXd& old_field,
                                      const Tissue& new_tissue, const FeMesh& new_mesh) {
  return transferConcentration(cellLineage(old_tissue), old_mesh, old_field, new_tissue, new_mesh);
}

Eigen::VectorXd transferConcentration(std::span<const std::int64_t> old_lineage, const FeMesh& old_mesh,
                                      const Eigen::VectorXd& old_field, const Tissue& new_tissue,
                                      const FeMesh& new_mesh) {
  Eigen::VectorXd out = interpolateNodalField(old_lineage, old_mesh, old_field, new_tissue, new_mesh);
  double old_total = 0.0, new_total = 0.0;
  for (double a : cellIntegrals(old_mesh, old_field, old_lineage.size())) old_total += a;
  for (double a : cellIntegrals(new_mesh, out, new_tissue.cellSlots())) new_total += a;
  if (new_total != 0.0) out *= old_total / new_total;
  return out;
}

}  // namespace tessella::mesh
