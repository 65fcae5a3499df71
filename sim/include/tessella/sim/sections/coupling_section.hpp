#pragma once
// The solver sections: `diffusion:` (one or several diffusing species on the
// tissue's finite-element mesh, with reaction terms), `compartments:` (one well-mixed concentration per
// cell, exchanged across walls, with polar transport) and `elasticity:`
// (linear elasticity of the tissue with boundary conditions on its faces).
// Each is off by default and read into a plain spec; the stages that solve
// them are in coupling_stages.hpp. See docs/solvers.md ("Coupling").
//
// Values written as "name=value, name=value" strings (per-cell-type
// coefficients, boundary conditions per region) are checked when the config
// is read, so a bad item is a ConfigError at its key.

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/solvers/assembly.hpp"
#include "tessella/solvers/diffusion_reaction.hpp"
#include "tessella/solvers/elasticity.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::sim {

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
  TimeScheme scheme = TimeScheme::ImplicitEuler;
  MassType mass = MassType::Consistent;
  std::size_t every = 1;
  /// Solver step; unset: one step over the whole time since the last solve.
  std::optional<double> dt;
  /// Integer cell property selecting per-type coefficients; empty: uniform.
  std::string type_property;

  bool hasReaction() const {
    for (const SpeciesSpec& s : species)
      if (!s.reaction.empty()) return true;
    return false;
  }
};

struct CompartmentSpec {
  /// Empty: no compartment stage.
  std::string field;
  TimeScheme scheme = TimeScheme::ImplicitEuler;
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
  ElasticModel model = ElasticModel::Solid;
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

void declareDiffusionSection(Schema& schema);
void declareCompartmentSection(Schema& schema);
void declareElasticitySection(Schema& schema);
DiffusionSpec readDiffusionSection(const Config& config);
CompartmentSpec readCompartmentSection(const Config& config);
ElasticitySpec readElasticitySection(const Config& config);

/// The cell properties the solver sections write (cell averages, amounts,
/// stresses), so other sections (division.gate) can check their names.
std::vector<std::string> coupledCellProperties(const DiffusionSpec& diffusion, const CompartmentSpec& compartments,
                                               const ElasticitySpec& elasticity);

}  // namespace tessella::sim
