// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The keys that assume a dimension or embedding of the tissue, checked
// against the tissue the config builds (or the snapshot it restarts from)
// when the config is read, so a mismatch is refused before anything is
// written instead of being ignored or found at the first solve.

#include "tissue_shape_checks.hpp"

#include <set>
#include <string>

#include "tessella/sim/sections/coupling_section.hpp"

namespace tessella::sim::detail {

namespace {

struct TissueShape {
  int dim = 2;
  Embedding embedding = Embedding::Planar;
  std::string source;  ///< what decided it, e.g. "tissue.generator: box_grid"

  bool planar() const { return embedding == Embedding::Planar; }
  std::string str() const {
    const char* kind = embedding == Embedding::Planar    ? "2D (flat, in the xy-plane)"
                       : embedding == Embedding::Surface ? "2D (a curved sheet)"
                                                         : "3D";
    return std::string(kind) + ", from " + source;
  }
};

TissueShape shapeOf(const Config& c, const TissueSpec& spec) {
  if (const auto* g = std::get_if<GeneratorSpec>(&spec)) {
    const GeneratedShape shape = g->shape();
    const std::string source = shape.decided_by.empty()
                                   ? "tissue.generator: " + g->name
                                   : "tissue." + g->name + "." + shape.decided_by + ": " +
                                         formatValue(g->params.get(shape.decided_by));
    return {shape.dim, shape.embedding, source};
  }
  if (const auto* import = std::get_if<ImportSpec>(&spec))
    return {import->tissue->dim(), import->tissue->embedding(), "the import of " + c.getString("tissue.import.file")};
  const auto& snap = std::get<SnapshotSpec>(spec);
  return {snap.tissue->dim(), snap.tissue->embedding(),
          "the snapshot " + c.getString("tissue.snapshot.file")};
}

/// Whether a key below `section` was written in the config file or a --set.
bool sectionGiven(const Config& c, const std::string& section) {
  for (const auto& [path, entry] : c.entries())
    if (path.rfind(section + ".", 0) == 0 && c.isGiven(path)) return true;
  return false;
}

/// A restart config that still describes the tissue it once generated (its
/// generator's section is given, though inactive) must restart a snapshot of
/// that dimension: a 3D snapshot under a config written for a 2D tissue is refused.
void checkSnapshotAgainstGenerators(const Config& c, const TissueShape& shape) {
  struct Described {
    std::string key;
    int dim;
  };
  std::vector<Described> described;
  for (const auto& g : generators().entries()) {
    const std::string section = "tissue." + g.name;
    if (!sectionGiven(c, section)) continue;
    // The shape its keys describe (defaults for the keys not given).
    const GeneratorSpec spec = describedGenerator(c, g.name);
    const GeneratedShape generated = spec.shape();
    described.push_back({generated.decided_by.empty() ? section
                                                      : section + " (" + generated.decided_by + ": " +
                                                            formatValue(spec.params.get(generated.decided_by)) + ")",
                         generated.dim});
  }
  std::set<int> dims;
  for (const Described& d : described) dims.insert(d.dim);
  if (dims.size() != 1 || *dims.begin() == shape.dim)
    return;  // none, agreeing, or no single dimension described
  throw c.errorAt("tissue.snapshot.file",
                  "the snapshot holds a " + std::to_string(shape.dim) +
                      "D tissue, but this config describes a " +
                      std::to_string(described.front().dim) + "D one (" + described.front().key +
                      "); restart from a snapshot of a " + std::to_string(described.front().dim) +
                      "D run, or remove that section if the config is meant for " +
                      std::to_string(shape.dim) + "D");
}

/// Regions z_min / z_max of a flat tissue are its whole boundary (every node has z = 0).
void checkRegion(const Config& c, const std::string& key, BoundaryRegion region,
                 const TissueShape& shape) {
  if (!shape.planar() || (region != BoundaryRegion::ZMin && region != BoundaryRegion::ZMax)) return;
  throw c.errorAt(key, std::string("boundary region '") + boundaryRegionName(region) +
                           "' needs a 3D tissue or a curved sheet; the tissue is " + shape.str() +
                           ", where every node has z = 0 (use 'all' for its whole boundary)");
}

void checkRegions(const Config& c, const std::string& key, const std::vector<RegionValue>& values,
                  const TissueShape& shape) {
  for (const RegionValue& r : values) checkRegion(c, key, r.region, shape);
}

/// A 3D-only mesh key set to something else than its default.
void checkMeshKey(const Config& c, const std::string& key, const TissueShape& shape) {
  if (shape.dim == 3 || !c.isGiven(key)) return;
  const KeySpec* spec = c.schema().findKey(key);
  if (spec && spec->default_value && *spec->default_value == c.entry(key).value) return;
  throw c.errorAt(key, formatValue(c.entry(key).value) +
                           " applies to 3D tissues (tetrahedra) only; the tissue is " +
                           shape.str());
}

}  // namespace

void checkTissueShape(const SimulationConfig& s) {
  const Config& c = s.config;
  const TissueShape shape = shapeOf(c, s.tissue);
  if (std::holds_alternative<SnapshotSpec>(s.tissue)) checkSnapshotAgainstGenerators(c, shape);

  // growth: a surface projection keeps a curved sheet on its surface.
  if (c.getString("growth.surface") != "none" &&
      !(shape.dim == 2 && shape.embedding == Embedding::Surface))
    throw c.errorAt("growth.surface", "'" + c.getString("growth.surface") +
                                          "' keeps a curved 2D sheet on a surface; the tissue is " +
                                          shape.str());

  // division: a fixed normal must cut a flat tissue's cells, so it needs an in-plane part.
  if (s.division.rule && c.getString("division.rule") == "fixed" && shape.planar()) {
    const Vec3 n = c.getVec("division.fixed_normal");
    if (!(Vec3(n.x(), n.y(), 0).norm() > 1e-12 * n.norm()))
      throw c.errorAt("division.fixed_normal",
                      formatValue(c.entry("division.fixed_normal").value) +
                          " is normal to the cells of a flat tissue, so no plane cuts them; "
                          "the tissue is " +
                          shape.str());
  }

  // diffusion: boundary regions.
  for (const SpeciesSpec& sp : s.diffusion.species) {
    checkRegions(c, sp.key_prefix + ".dirichlet", sp.dirichlet, shape);
    checkRegions(c, sp.key_prefix + ".flux", sp.flux, shape);
    checkRegions(c, sp.key_prefix + ".robin", sp.robin, shape);
  }

  // compartments: polar transport along a direction with a part in the tissue's plane.
  if (!s.compartments.field.empty() && s.compartments.polar_rate > 0 && shape.planar()) {
    const Vec3& d = s.compartments.polar_direction;
    if (!(Vec3(d.x(), d.y(), 0).norm() > 1e-12 * d.norm()))
      throw c.errorAt(
          "compartments.polar.direction",
          formatValue(c.entry("compartments.polar.direction").value) +
              " is normal to a flat tissue, so no wall lies downstream; the tissue is " +
              shape.str());
  }

  // elasticity: plane models for flat 2D tissues, solid for 3D ones; 2D has no z.
  const ElasticitySpec& e = s.elasticity;
  if (e.enabled) {
    const std::string model = c.getString("elasticity.model");
    if (e.model == solvers::ElasticModel::Solid && shape.dim != 3)
      throw c.errorAt("elasticity.model",
                      "'solid' needs a 3D tissue; the tissue is " + shape.str() +
                          " (use plane_stress or plane_strain for a flat 2D tissue)");
    if (e.model != solvers::ElasticModel::Solid && !(shape.dim == 2 && shape.planar()))
      throw c.errorAt("elasticity.model", "'" + model + "' needs a flat 2D tissue; the tissue is " +
                                              shape.str() + (shape.dim == 3 ? " (use solid)" : ""));
    for (const auto& [region, fixed] : e.fixed) {
      checkRegion(c, "elasticity.fixed", region, shape);
      if (fixed[2] && e.model != solvers::ElasticModel::Solid)
        throw c.errorAt("elasticity.fixed",
                        std::string("component z (on '") + boundaryRegionName(region) +
                            "') does not exist in the 2D model '" + model +
                            "' (displacements x and y); the tissue is " + shape.str());
    }
    if (e.stretch_region) checkRegion(c, "elasticity.stretch_region", *e.stretch_region, shape);
    if (e.traction_region) {
      checkRegion(c, "elasticity.traction_region", *e.traction_region, shape);
      if (e.model != solvers::ElasticModel::Solid && e.traction.z() != 0)
        throw c.errorAt("elasticity.traction",
                        formatValue(c.entry("elasticity.traction").value) +
                            " has a z component, which the 2D model '" + model +
                            "' has no displacement for; the tissue is " + shape.str());
    }
  }

  // mechanics: the wall-spring model is for flat 2D tissues, membranes for curved sheets and 3D tissues.
  if (s.mechanics.enabled && !s.mechanics.membranes && !(shape.dim == 2 && shape.planar()))
    throw c.errorAt("mechanics.model", "'" + c.getString("mechanics.model") +
                                           "' needs a flat 2D tissue; the tissue is " + shape.str() +
                                           " (curved sheets and 3D tissues: model membranes)");
  if (s.mechanics.enabled && s.mechanics.membranes && shape.dim == 2 && shape.planar())
    throw c.errorAt("mechanics.model", "'membranes' needs a curved sheet or a 3D tissue; the tissue is " +
                                           shape.str() + " (use wall_springs)");
  if (s.mechanics.enabled && s.mechanics.membranes && shape.dim == 3 &&
      s.mechanics.membrane.support == mechanics::MembraneGrowthParams::Support::Boundary)
    throw c.errorAt("mechanics.membrane_support", "'boundary' holds a sheet's rims; the tissue is " + shape.str() +
                                                      " (use base)");

  // mesh: keys for tetrahedra only.
  for (const char* key : {"mesh.max_volume", "mesh.radius_edge_ratio", "mesh.min_dihedral_angle",
                          "mesh.volume_method"})
    checkMeshKey(c, key, shape);
}

}  // namespace tessella::sim::detail
