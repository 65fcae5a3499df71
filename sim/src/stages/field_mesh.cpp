// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/stages/field_mesh.hpp"

#include <stdexcept>

#include "tessella/mesh/field_transfer.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::sim {

FieldMesh::FieldMesh(mesh::MeshOptions options) : options_(options) { mesh::validateMeshOptions(options_); }

bool FieldMesh::meshes(const Tissue& tissue) const {
  return meshed_ && !stale_ && topology_ == tissue.topologyVersion() && geometry_ == tissue.geometryVersion();
}

bool FieldMesh::update(const Tissue& tissue) {
  if (meshes(tissue)) return false;
  mesh::FeMesh fresh = mesh::meshTissue(tissue, options_);
  std::map<std::string, Eigen::VectorXd> carried;
  for (const std::string& name : carried_) {
    const auto it = fields_.find(name);
    if (it == fields_.end()) continue;
    try {
      carried[name] = mesh::transferConcentration(lineage_, mesh_, it->second, tissue, fresh);
    } catch (const InputError& e) {
      // Cells more than one division away from the last mesh: solve more often.
      throw InputError("cannot carry field '" + name + "' to the new mesh: " + e.what() +
                       " (solve at least once between two divisions of a cell: lower `every`)");
    }
  }
  mesh_ = std::move(fresh);
  fields_ = std::move(carried);
  lineage_ = mesh::cellLineage(tissue);
  meshed_ = true;
  stale_ = false;
  topology_ = tissue.topologyVersion();
  geometry_ = tissue.geometryVersion();
  ++version_;
  cell_measures_ = tessella::mesh::cellIntegrals(mesh_, Eigen::VectorXd::Ones(mesh_.numNodes()), lineage_.size());
  return true;
}

void FieldMesh::restore(mesh::FeMesh mesh, std::vector<std::int64_t> cell_lineage,
                        std::map<std::string, Eigen::VectorXd> fields, const std::set<std::string>& carried,
                        const Tissue* current) {
  for (const auto& [name, values] : fields)
    if (values.size() != mesh.numNodes())
      throw InputError("field '" + name + "' has " + std::to_string(values.size()) + " values for a mesh of " +
                       std::to_string(mesh.numNodes()) + " nodes");
  for (Eigen::Index e = 0; e < mesh.element_cell.size(); ++e)
    if (mesh.element_cell[e] < 0 || static_cast<std::size_t>(mesh.element_cell[e]) >= cell_lineage.size())
      throw InputError("element " + std::to_string(e) + " of the mesh lies in cell " +
                       std::to_string(mesh.element_cell[e]) + ", which its " + std::to_string(cell_lineage.size()) +
                       " cells do not include");
  mesh_ = std::move(mesh);
  lineage_ = std::move(cell_lineage);
  fields_ = std::move(fields);
  carried_.clear();
  for (const auto& [name, values] : fields_)
    if (carried.count(name)) carried_.insert(name);
  meshed_ = true;
  stale_ = current == nullptr;
  if (current) {
    topology_ = current->topologyVersion();
    geometry_ = current->geometryVersion();
  }
  ++version_;
  cell_measures_ = tessella::mesh::cellIntegrals(mesh_, Eigen::VectorXd::Ones(mesh_.numNodes()), lineage_.size());
}

const mesh::FeMesh& FieldMesh::mesh() const {
  if (!meshed_) throw std::logic_error("FieldMesh::mesh: no mesh yet (call update first)");
  return mesh_;
}

void FieldMesh::setField(const std::string& name, Eigen::VectorXd values, bool carried) {
  if (values.size() != mesh().numNodes())
    throw InputError("field '" + name + "' has " + std::to_string(values.size()) + " values for a mesh of " +
                     std::to_string(mesh_.numNodes()) + " nodes");
  fields_[name] = std::move(values);
  if (carried)
    carried_.insert(name);
  else
    carried_.erase(name);
}

const Eigen::VectorXd& FieldMesh::field(const std::string& name) const {
  const auto it = fields_.find(name);
  if (it == fields_.end()) throw std::logic_error("FieldMesh::field: no field '" + name + "'");
  return it->second;
}

std::vector<double> FieldMesh::cellIntegrals(const Eigen::VectorXd& field) const {
  return tessella::mesh::cellIntegrals(mesh(), field, lineage_.size());
}

}  // namespace tessella::sim
