// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The `mechanics:` section (docs/mechanics.md): turgor-driven growth of a
// planar 2D tissue. Every step the walls (edges) are linear elastic springs
// with a rest length, the cells push with their turgor pressure, the
// quasi-static equilibrium is solved by Newton (mechanics/equilibrium.hpp) and
// the tissue moves there; then the rest lengths grow where the walls are
// strained beyond a threshold (Lockhart-Ortega). Per wall the tissue keeps
// rest_length, wall_strain and wall_tension (wall properties); per cell
// turgor_pressure, the length-weighted means of its walls' strain and
// tension (mean_wall_strain, mean_wall_tension) and the stress its walls carry
// (wall_stress, stress_max, stress_min, stress_direction; wall_stress.hpp),
// which reach the VTU output.
// The `elasticity:` section (a linear solve that moves nothing) is separate
// and unchanged.

#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "tessella/mechanics/tissue_membranes.hpp"
#include "tessella/io/wall_vtu.hpp"
#include "tessella/mechanics/turgor_growth_step.hpp"
#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/sim/sections/section_unit.hpp"
#include "tessella/sim/stages/stage.hpp"

namespace tessella::sim {

/// How the tissue is held against rigid motions.
enum class MechanicsSupport { Point, Region };

struct MechanicsSpec {
  bool enabled = false;
  /// `wall_springs` (planar tissues) or `membranes` (curved sheets, 3D tissues).
  bool membranes = false;
  /// The membrane model's material, fibres, growth law, support (base or rim) and
  /// solver options (pressure, young, thickness, growth and solver as params).
  mechanics::MembraneGrowthParams membrane{};
  /// Soft summit: a cell's Young's modulus is young (f + (1 - f) min(r / R, 1)^2),
  /// r its centroid's distance from the vertical axis through soft_center
  /// (default: the vertex mean at the start); R = 0: uniform.
  double soft_radius = 0.0;
  double soft_factor = 1.0;
  std::optional<Vec3> soft_center;
  /// Material, pressure, growth law and solver options (params.supports is
  /// filled by the stage from the fields below, for the tissue of each step).
  mechanics::TurgorGrowthParams params{};
  MechanicsSupport support = MechanicsSupport::Point;
  /// The pinned point; absent: the tissue's centroid when the run starts.
  std::optional<Vec3> pin_point;
  /// With Region: the side of the bounding box whose vertices are fixed:
  /// 0 x_min, 1 x_max, 2 y_min, 3 y_max.
  int fixed_side = 0;
};

class MechanicsStage final : public Stage {
 public:
  explicit MechanicsStage(MechanicsSpec spec);
  std::string name() const override { return "mechanics"; }
  void prepare(Tissue& tissue, double time) override;
  void apply(Tissue& tissue, const StepContext& context) override;
  std::vector<std::string> cellPropertiesWritten() const override;
  /// The walls' rest lengths (live walls in slot order, exact text) and the
  /// pinned point, in the run state as mechanics.rest_length and
  /// mechanics.pin_point: VTU snapshots hold no wall properties, and a
  /// restart continues from them bit for bit. Membranes: their rest state
  /// (mechanics.membrane_rest), base height and soft centre, and on a 3D
  /// tissue the wall columns they read (mechanics.wall.fibre_ratio,
  /// mechanics.wall.membrane_rest_ratio: policy, default, value per live wall).
  void saveState(const Tissue& tissue, const std::string& snapshot_path, const io::VtuOptions& options,
                 io::RunState& state) const override;
  /// Also writes the walls' mechanics beside the snapshot, <stem>.walls.vtu
  /// (io::writeWallsVtu; docs/output.md): a planar tissue's wall springs
  /// (rest_length, wall_strain, wall_tension, growth_rate and the unit vector
  /// wall_direction) or a 3D tissue's membrane walls
  /// (mechanics::membraneWallOutputNames()); a curved sheet's membranes are
  /// its cells, whose outputs the snapshot holds (no walls file).
  /// A snapshot without that state (an initial tissue, or a run without the
  /// section) starts with its walls at rest in its shape.
  void continueFrom(const std::string& snapshot_path, const io::RunState& state) override;
  /// "walls": the walls files are listed in <series>.walls.pvd.
  std::vector<std::string> besideFileTags() const override { return {"walls"}; }
  /// The arrays of the walls file of `tissue` (empty for a curved sheet).
  io::WallArrays wallArrays(const Tissue& tissue) const;
  /// wallArrays(): the mesh series shows the walls file's values on each wall's facets.
  io::WallArrays meshWallArrays(const Tissue& tissue) const override { return wallArrays(tissue); }
  /// A curved sheet's membranes are its cells: their outputs, the cell
  /// columns named in mechanics::membraneWallOutputNames() (wall_stress,
  /// stress_max, stress_min, stress_direction, strain_max, strain_min,
  /// growth_rate) and turgor_pressure, for the mesh series' elements. Empty
  /// for a 3D tissue (its membranes are its walls: meshWallArrays) and for
  /// wall springs.
  io::WallArrays meshCellArrays(const Tissue& tissue) const override;
  /// The names meshCellArrays reads (those the cells have).
  static std::vector<std::string> sheetCellOutputNames();
  /// The last step's report (Newton iterations, residuals, strains).
  const mechanics::TurgorStepReport& lastReport() const { return report_; }
  /// The last step's report of the membrane model.
  const mechanics::MembraneStepReport& lastMembraneReport() const { return membrane_report_; }
  static constexpr const char* kMeanStrainName = "mean_wall_strain";
  static constexpr const char* kMeanTensionName = "mean_wall_tension";

 private:
  void writeCellMeans(Tissue& tissue) const;
  void restore(Tissue& tissue);
  void applyMembranes(Tissue& tissue, const StepContext& context);
  MechanicsSpec spec_;
  mechanics::MembraneRestState membrane_state_;
  mechanics::MembraneStepReport membrane_report_;
  mechanics::TurgorStepReport report_;
  std::optional<std::pair<std::string, io::RunState>> restart_;  // snapshot path, its run state
};

void declareMechanicsSection(Schema& schema);
MechanicsSpec readMechanicsSection(const Config& config);
void addMechanicsStage(const MechanicsSpec& spec, StageList& stages);

}  // namespace tessella::sim
