// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "coupling_cells.hpp"

#include <algorithm>
#include <cmath>
#include <typeindex>
#include <unordered_map>

#include "tessella/solvers/facets.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::sim::detail {

Eigen::VectorXd perCell(const Tissue& tissue, const CellCoefficient& k, const std::string& type_property,
                        const std::string& section) {
  Eigen::VectorXd v = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(std::max<std::size_t>(tissue.cellSlots(), 1)),
                                                k.uniform);
  if (k.by_type.empty()) return v;
  const PropertyColumnBase* column = tissue.cellProperties().find(type_property);
  if (!column)
    throw InputError(section + ".by_property: the tissue has no cell property '" + type_property + "'");
  if (column->type() != std::type_index(typeid(std::int64_t)))
    throw InputError(section + ".by_property: cell property '" + type_property + "' is not an integer column");
  const auto& types = tissue.cellProperties().get<std::int64_t>(type_property);
  for (CellId c : tissue.cells())
    if (const auto it = k.by_type.find(types[c]); it != k.by_type.end()) v[c.index()] = it->second;
  return v;
}

void markCells(Tissue& tissue, const std::string& name, const std::vector<std::int64_t>& lineage_ids,
               const Vec3& center, double radius, const std::string& what) {
  PropertyStore& store = tissue.cellProperties();
  // Chosen once, on the initial tissue: a tissue read back from a snapshot
  // of the run already carries its marks (a restart must not mark the cells
  // that have since grown into the region).
  if (store.has(name)) return;
  store.add<std::int64_t>(name, 0, DivisionPolicy::Copy);
  auto& mark = store.get<std::int64_t>(name);
  std::unordered_map<std::int64_t, CellId> by_lineage;
  for (CellId c : tissue.cells()) by_lineage.emplace(tissue.lineageId(c), c);
  for (std::int64_t id : lineage_ids) {
    const auto it = by_lineage.find(id);
    if (it == by_lineage.end())
      throw InputError(what + ": no live cell has lineage id " + std::to_string(id) + " (the tissue has " +
                       std::to_string(tissue.numCells()) + " cells)");
    mark[it->second] = 1;
  }
  if (radius > 0)
    for (CellId c : tissue.cells())
      if ((cellCentroid(tissue, c) - center).norm() <= radius) mark[c] = 1;
}

std::vector<bool> marked(const Tissue& tissue, const std::string& name) {
  std::vector<bool> out(tissue.cellSlots(), false);
  if (!tissue.cellProperties().has(name)) return out;
  const auto& mark = tissue.cellProperties().get<std::int64_t>(name);
  for (CellId c : tissue.cells()) out[c.index()] = mark[c] != 0;
  return out;
}

std::vector<int> regionFacets(const mesh::FeMesh& mesh, BoundaryRegion region, const std::string& what) {
  std::vector<int> facets;
  if (region == BoundaryRegion::All) {
    facets = solvers::boundaryFacets(mesh);
  } else {
    const int r = static_cast<int>(region) - 1;  // x_min, x_max, y_min, ...
    const int axis = r / 2;
    const bool high = r % 2 == 1;
    const Eigen::Vector3d lo = mesh.nodes.colwise().minCoeff(), hi = mesh.nodes.colwise().maxCoeff();
    const double tol = 1e-6 * std::max((hi - lo).norm(), 1e-300);
    const double bound = high ? hi[axis] : lo[axis];
    for (int f = 0; f < mesh.numWallFacets(); ++f) {
      if (!mesh.facet_on_boundary[f]) continue;
      bool on = true;
      for (int k = 0; k < mesh.wall_facets.cols() && on; ++k)
        on = std::abs(mesh.nodes(mesh.wall_facets(f, k), axis) - bound) <= tol;
      if (on) facets.push_back(f);
    }
  }
  if (facets.empty())
    throw InputError(what + ": boundary region '" + boundaryRegionName(region) +
                     "' holds no boundary wall facet of the tissue's mesh");
  return facets;
}

PropertyColumn<double>& doubleColumn(Tissue& tissue, const std::string& name, DivisionPolicy policy) {
  PropertyStore& store = tissue.cellProperties();
  if (const PropertyColumnBase* c = store.find(name)) {
    if (c->type() != std::type_index(typeid(double)))
      throw InputError("cell property '" + name + "' exists and does not hold numbers (double)");
    return store.get<double>(name);
  }
  return store.add<double>(name, 0.0, policy);
}

}  // namespace tessella::sim::detail
