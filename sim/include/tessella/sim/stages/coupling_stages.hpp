#pragma once
// The solver stages of a Simulation (see stage.hpp, coupling_section.hpp).
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

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessella/sim/sections/coupling_section.hpp"
#include "tessella/sim/stages/field_mesh.hpp"
#include "tessella/sim/stages/stage.hpp"
#include "tessella/solvers/diffusion_reaction.hpp"

namespace tessella::sim {

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
  /// Marks the source cells; transient: meshes and sets the initial field.
  void prepare(Tissue& tissue, double time) override;
  void apply(Tissue& tissue, const StepContext& context) override;
  std::size_t solves() const { return schedule_.solves(); }
  /// Total amount (integral) of species `k` (in the order of the spec) after the last solve.
  double totalAmount(std::size_t k = 0) const { return total_.at(k); }

 private:
  DiffusionSpec spec_;
  void storeCellValues(Tissue& tissue);

  SolveSchedule schedule_;
  std::optional<DiffusionReaction> solver_;
  std::shared_ptr<detail::ReactionTerms> reaction_;  // the compiled reaction expressions, if any
  std::uint64_t solver_mesh_version_ = 0;
  std::vector<double> total_;
};

class CompartmentStage final : public Stage {
 public:
  explicit CompartmentStage(CompartmentSpec spec);
  std::string name() const override { return "compartments"; }
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
  void apply(Tissue& tissue, const StepContext& context) override;
  std::size_t solves() const { return schedule_.solves(); }

 private:
  ElasticitySpec spec_;
  SolveSchedule schedule_;
};

}  // namespace tessella::sim
