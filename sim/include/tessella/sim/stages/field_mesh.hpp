// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// FieldMesh: the finite-element mesh of a simulation's tissue and the nodal
// fields the solver stages keep on it. update() rebuilds the mesh only when
// the tissue's topology or geometry changed since the last mesh, and carries
// every carried field to the new mesh with mesh::transferConcentration
// (P1 interpolation by lineage, then one rescaling so the total amount is
// conserved across growth and divisions). Fields that are recomputed at
// every solve (displacements) are not carried: they are dropped on a remesh.
//
// The solver stages share one FieldMesh, so a tissue is meshed once per
// change however many solvers run; the mesh series output reads it. Of the
// tissue it meshed it keeps the lineage id of each cell slot (all the
// transfer needs), so that a restart can restore it (restore()).

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

#include <Eigen/Core>

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/mesh/mesh_options.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::sim {

class FieldMesh {
 public:
  explicit FieldMesh(mesh::MeshOptions options = {});

  /// Meshes the tissue if it changed since the last mesh (or was never
  /// meshed) and transfers the carried fields. Returns true when it remeshed.
  bool update(const Tissue& tissue);
  bool hasMesh() const { return meshed_; }
  /// Whether `tissue` is the tissue the current mesh was made of, unchanged
  /// since (update() would not remesh it).
  bool meshes(const Tissue& tissue) const;
  /// The lineage id of each cell slot of the tissue as it was meshed (-1 for
  /// dead slots): FeMesh::element_cell indexes it.
  const std::vector<std::int64_t>& meshedLineage() const { return lineage_; }
  /// Carried fields are transferred to the next mesh; the others are dropped.
  bool carried(const std::string& name) const { return carried_.count(name) > 0; }

  /// Continues the state a snapshot saved: `mesh` made of a tissue whose
  /// cell slots had the lineage ids `cell_lineage` (element_cell indexes
  /// it), with its fields (those named in `carried` are carried). `current`:
  /// the tissue the run continues with, when it is that tissue unchanged (the
  /// next update() then keeps the mesh until it changes); null: the next
  /// update() remeshes. InputError when the fields do not fit the mesh.
  void restore(mesh::FeMesh mesh, std::vector<std::int64_t> cell_lineage,
               std::map<std::string, Eigen::VectorXd> fields, const std::set<std::string>& carried,
               const Tissue* current);
  /// The current mesh; std::logic_error before the first update().
  const mesh::FeMesh& mesh() const;
  /// Incremented at every remesh (solvers rebuild their systems when it moves).
  std::uint64_t version() const { return version_; }
  std::size_t remeshes() const { return static_cast<std::size_t>(version_); }

  /// Stores a nodal field (size = nodes of the current mesh; InputError otherwise).
  void setField(const std::string& name, Eigen::VectorXd values, bool carried);
  bool hasField(const std::string& name) const { return fields_.count(name) > 0; }
  const Eigen::VectorXd& field(const std::string& name) const;
  const std::map<std::string, Eigen::VectorXd>& fields() const { return fields_; }

  /// Per cell slot of the meshed tissue: the mesh measure of each cell and
  /// the integral of a nodal field over it (exact for P1).
  const std::vector<double>& cellMeasures() const { return cell_measures_; }
  std::vector<double> cellIntegrals(const Eigen::VectorXd& field) const;

 private:
  mesh::MeshOptions options_;
  bool meshed_ = false;
  bool stale_ = false;  // restored without the tissue it was made of: remesh at the next update()
  std::vector<std::int64_t> lineage_;  // of the tissue as it was meshed, by cell slot (for the transfer)
  std::uint64_t topology_ = 0, geometry_ = 0;
  mesh::FeMesh mesh_;
  std::uint64_t version_ = 0;
  std::map<std::string, Eigen::VectorXd> fields_;
  std::set<std::string> carried_;
  std::vector<double> cell_measures_;
};

}  // namespace tessella::sim
