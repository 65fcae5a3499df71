// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The solver stages of a Simulation (see stage.hpp) and their parameters,
// which the solver sections read (coupling_section.hpp) or a model builds.
// Each solves every `every` steps, after growth and division, over the time
// since its previous solve:
//   DiffusionStage    remeshes the tissue if it changed (FieldMesh, shared),
//                     carries the species over, solves all of them with one
//                     DiffusionReaction (transient or steady; reactions from
//                     the config's expressions) and stores the nodal fields
//                     on the FieldMesh and the cell averages / amounts as
//                     cell properties;
//   CompartmentStage  one concentration per cell, the amounts kept as a cell
//                     property split by measure at division (no mesh);
//   ElasticityStage   remeshes if needed and solves the current shape;
//                     displacements on the FieldMesh, stresses per cell.

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tessella/sim/stages/field_mesh.hpp"
#include "tessella/sim/stages/stage.hpp"
#include "tessella/solvers/assembly.hpp"
#include "tessella/solvers/diffusion_reaction.hpp"
#include "tessella/solvers/elasticity.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::sim {

// --- the stages' parameters (the solver sections read them from YAML) --------

/// A part of the tissue boundary chosen by position: every boundary wall
/// facet (`all`), or the facets lying on a face of the tissue's bounding box
/// (`x_min` = the facets whose nodes all have x = the smallest x, within
/// 1e-6 of the box diagonal).
enum class BoundaryRegion { All, XMin, XMax, YMin, YMax, ZMin, ZMax };
const std::vector<std::string>& boundaryRegionNames();
const char* boundaryRegionName(BoundaryRegion region);

struct RegionValue {
  BoundaryRegion region = BoundaryRegion::All;
  double value = 0.0;
};

/// A coefficient uniform over the tissue, or by cell type: the value of the
/// cell property named by the section's `by_property` (an integer) selects the entry of
/// `by_type`, and types not listed take `uniform`.
struct CellCoefficient {
  double uniform = 0.0;
  std::map<std::int64_t, double> by_type;
};

/// Source cells: chosen once, at the first solve, among the cells whose
/// centroid lies within `radius` of `center` and the cells whose lineage id is
/// listed; marked with the cell property `<name>_source` (copied at
/// division, so daughters of a source cell are sources). They get the extra
/// production `rate`.
struct SourceSpec {
  double rate = 0.0;
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
  std::vector<std::int64_t> lineage_ids;
};

/// One diffusing species: its name (the name of its outputs and of its
/// variable in reaction expressions), coefficients and boundary conditions.
struct SpeciesSpec {
  std::string name;
  /// Where its keys are in the config: "diffusion" (single-species form) or
  /// "diffusion.species_map.<name>"; error messages name keys under it.
  std::string key_prefix = "diffusion";
  double initial = 0.0;
  CellCoefficient diffusivity{1.0, {}}, decay{0.0, {}}, production{0.0, {}};
  SourceSpec source;
  std::vector<RegionValue> dirichlet, flux, robin;
  double robin_exterior = 0.0;
  /// Reaction rate r(species...) added to du/dt, a muparser expression in
  /// the species names; empty: none. Checked when the config is read.
  std::string reaction;
};

struct DiffusionSpec {
  /// Empty: no diffusion stage. Several species share the mesh, the solver
  /// (one DiffusionReaction) and the keys below.
  std::vector<SpeciesSpec> species;
  bool steady = false;
  solvers::TimeScheme scheme = solvers::TimeScheme::ImplicitEuler;
  solvers::MassType mass = solvers::MassType::Consistent;
  std::size_t every = 1;
  /// Solver step; unset: one step over the whole time since the last solve.
  std::optional<double> dt;
  /// Integer cell property selecting per-type coefficients; empty: uniform.
  std::string type_property;
  /// A restart from a snapshot starts the species afresh instead of
  /// continuing the state saved beside it (diffusion.restart: fresh).
  bool fresh_restart = false;

  bool hasReaction() const {
    for (const SpeciesSpec& s : species)
      if (!s.reaction.empty()) return true;
    return false;
  }
};

struct CompartmentSpec {
  /// Empty: no compartment stage.
  std::string field;
  solvers::TimeScheme scheme = solvers::TimeScheme::ImplicitEuler;
  std::size_t every = 1;
  std::optional<double> dt;
  double initial = 0.0;
  std::string type_property;
  CellCoefficient permeability{1.0, {}}, decay{0.0, {}}, production{0.0, {}};
  SourceSpec source;
  /// Polar (active) transport: a pumping cell moves `polar_rate` * wall area
  /// * its concentration per unit time across each wall to a neighbour whose
  /// centroid lies downstream along `polar_direction`.
  double polar_rate = 0.0;
  Vec3 polar_direction = Vec3(1, 0, 0);
  /// Lineage ids of the pumping cells (from polar.cells); empty with
  /// polar_all: every cell pumps.
  std::vector<std::int64_t> polar_cells;
  bool polar_all = true;
};

struct ElasticitySpec {
  bool enabled = false;
  solvers::ElasticModel model = solvers::ElasticModel::Solid;
  std::size_t every = 1;
  std::string type_property;
  CellCoefficient young{1.0, {}}, poisson{0.3, {}};
  double thickness = 1.0;
  /// Components (x, y, z) fixed to zero on each region.
  std::vector<std::pair<BoundaryRegion, std::array<bool, 3>>> fixed;
  /// A region displaced along its own axis (x_max: +x) by `stretch`.
  std::optional<BoundaryRegion> stretch_region;
  double stretch = 0.0;
  std::optional<BoundaryRegion> traction_region;
  Vec3 traction = Vec3::Zero();
};

// --- the stages -------------------------------------------------------------

namespace detail {
class ReactionTerms;
}

/// Solves every `every` steps over the time since the last solve.
class SolveSchedule {
 public:
  explicit SolveSchedule(std::size_t every) : every_(every) {}
  /// Whether step `context.step` ends with a solve; records the start time
  /// at the first call.
  bool due(const StepContext& context);
  /// Time since the previous solve (or the start), to the end of this step.
  double elapsed(const StepContext& context) const { return context.time + context.dt - last_; }
  void solved(const StepContext& context) { last_ = context.time + context.dt; ++solves_; }
  std::size_t solves() const { return solves_; }

 private:
  std::size_t every_;
  std::optional<double> start_;
  double last_ = 0.0;
  std::size_t solves_ = 0;
};

/// A stage that keeps fields on the shared FieldMesh (the mesh series shows them).
class MeshFieldStage : public Stage {
 public:
  explicit MeshFieldStage(std::shared_ptr<FieldMesh> mesh) : mesh_(std::move(mesh)) {}
  const std::shared_ptr<FieldMesh>& fieldMesh() const { return mesh_; }

 protected:
  std::shared_ptr<FieldMesh> mesh_;
};

class DiffusionStage final : public MeshFieldStage {
 public:
  DiffusionStage(DiffusionSpec spec, std::shared_ptr<FieldMesh> mesh);
  std::string name() const override { return "diffusion"; }
  /// <species> (cell average) and <species>_amount, for every species.
  std::vector<std::string> cellPropertiesWritten() const override;
  /// Marks the source cells; transient: meshes and sets the initial field.
  /// After continueFrom(): restores the mesh and fields saved beside the
  /// snapshot instead (unless spec.fresh_restart).
  void prepare(Tissue& tissue, double time) override;
  void apply(Tissue& tissue, const StepContext& context) override;
  std::size_t solves() const { return schedule_.solves(); }
  /// Total amount (integral) of species `k` (in the order of the spec) after the last solve.
  double totalAmount(std::size_t k = 0) const { return total_.at(k); }

  /// Run state diffusion.* (species, mode, totals) and, once there is a
  /// mesh, the mesh with every field as io::FieldState beside the snapshot
  /// (diffusion.fields names it, diffusion.fields.crc32 its checksum,
  /// diffusion.fields.current whether the tissue is the one meshed,
  /// diffusion.fields.carried the carried fields).
  void saveState(const Tissue& tissue, const std::string& snapshot_path, const io::VtuOptions& options,
                 io::RunState& state) const override;
  void continueFrom(const std::string& snapshot_path, const io::RunState& state) override;

 private:
  DiffusionSpec spec_;
  void storeCellValues(Tissue& tissue);
  /// Restores what saveState() saved; false when there is nothing to
  /// restore (a tissue file that is not a run's snapshot). InputError naming
  /// the snapshot or the field state file when it is missing or does not fit.
  bool restore(const Tissue& tissue);

  struct Restart {
    std::string snapshot;
    io::RunState state;
  };
  std::optional<Restart> restart_;

  SolveSchedule schedule_;
  std::optional<solvers::DiffusionReaction> solver_;
  std::shared_ptr<detail::ReactionTerms> reaction_;  // the compiled reaction expressions, if any
  std::uint64_t solver_mesh_version_ = 0;
  std::vector<double> total_;
};

class CompartmentStage final : public Stage {
 public:
  explicit CompartmentStage(CompartmentSpec spec);
  std::string name() const override { return "compartments"; }
  /// <field> (concentration) and <field>_amount.
  std::vector<std::string> cellPropertiesWritten() const override;
  /// Marks source and pumping cells and sets the initial amounts.
  void prepare(Tissue& tissue, double time) override;
  void apply(Tissue& tissue, const StepContext& context) override;
  std::size_t solves() const { return schedule_.solves(); }

 private:
  CompartmentSpec spec_;
  SolveSchedule schedule_;
};

class ElasticityStage final : public MeshFieldStage {
 public:
  ElasticityStage(ElasticitySpec spec, std::shared_ptr<FieldMesh> mesh);
  std::string name() const override { return "elasticity"; }
  /// stressPropertyNames().
  std::vector<std::string> cellPropertiesWritten() const override { return stressPropertyNames(); }
  /// The cell-averaged stress: the six components in the solver's order
  /// (stress_xx, stress_yy, stress_zz, stress_yz, stress_xz, stress_xy), then
  /// the largest principal stress (stress_max_principal).
  static const std::vector<std::string>& stressPropertyNames();
  void apply(Tissue& tissue, const StepContext& context) override;
  std::size_t solves() const { return schedule_.solves(); }

 private:
  ElasticitySpec spec_;
  SolveSchedule schedule_;
};

}  // namespace tessella::sim
