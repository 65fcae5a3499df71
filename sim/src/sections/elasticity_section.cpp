// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "coupling_values.hpp"
#include "tessella/sim/sections/coupling_section.hpp"

namespace tessella::sim {

namespace {
// The models of a tissue's own shape: a membrane (a curved sheet without
// bending stiffness) needs loads the section does not offer.
std::vector<std::string> tissueModels() {
  std::vector<std::string> names;
  for (const auto& e : solvers::elasticModels().entries())
    if (e.value != solvers::ElasticModel::Membrane) names.push_back(e.name);
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

std::vector<std::string> regionChoices() {
  std::vector<std::string> c = {"none"};
  for (const auto& r : boundaryRegionNames()) c.push_back(r);
  return c;
}
}  // namespace

void declareElasticitySection(Schema& s) {
  s.section("elasticity",
            "Linear elasticity (small strains, P1) of the tissue's current shape under boundary "
            "conditions on faces of its bounding box: plane stress / plane strain for flat 2D tissues, "
            "solid for 3D ones. Nodal displacements go to the mesh series (displacement_x/_y/_z), the "
            "cell-averaged stress to the tissue (" + joined(ElasticityStage::stressPropertyNames()) +
                "). The displacement is not applied to the tissue. Off unless `model` is set. See "
                "docs/solvers.md.");
  s.key("elasticity.model", ValueType::Enum, "The elastic model.")
      .oneOf(withNone(tissueModels()))
      .byDefault(std::string("none"));
  const Condition on{"elasticity.model", tissueModels()};
  detail::declareEveryAndStep(s, "elasticity", on);
  s.key("elasticity.young", ValueType::Float, "Young's modulus E.").byDefault(1.0).above(0).activeWhen(on.key, on.values);
  detail::declarePerTypeKey(s, "elasticity.young_by", "Young's modulus per cell type, e.g. \"0=1, 1=10\".", on);
  s.key("elasticity.poisson", ValueType::Float, "Poisson's ratio nu.")
      .byDefault(0.3)
      .above(-1)
      .activeWhen(on.key, on.values);
  detail::declarePerTypeKey(s, "elasticity.poisson_by", "Poisson's ratio per cell type.", on);
  s.key("elasticity.thickness", ValueType::Float, "Thickness of a 2D tissue (scales stiffness and loads).")
      .byDefault(1.0)
      .above(0)
      .activeWhen("elasticity.model", {solvers::elasticModels().name(solvers::ElasticModel::PlaneStress),
                                       solvers::elasticModels().name(solvers::ElasticModel::PlaneStrain)});
  s.key("elasticity.fixed", ValueType::String,
        "Displacement components held at zero per boundary region, e.g. \"x_min=x, y_min=y, z_min=z\" "
        "(symmetry planes) or \"x_min=xyz\" (clamped). The body must be held against every rigid motion.")
      .isRequired()
      .activeWhen(on.key, on.values);
  s.key("elasticity.stretch_region", ValueType::Enum,
        "A boundary region displaced along its own axis (x_min/x_max: x, ...) by `stretch`.")
      .oneOf(regionChoices())
      .byDefault(std::string("none"))
      .activeWhen(on.key, on.values);
  s.key("elasticity.stretch", ValueType::Float, "Displacement of the stretched region (positive: +axis).")
      .byDefault(0.0)
      .activeWhen(on.key, on.values);
  s.key("elasticity.traction_region", ValueType::Enum, "A boundary region loaded by the traction `traction`.")
      .oneOf(regionChoices())
      .byDefault(std::string("none"))
      .activeWhen(on.key, on.values);
  s.key("elasticity.traction", ValueType::Vec3, "Force per unit area (2D: per unit length and thickness).")
      .byDefault(std::vector<double>{0, 0, 0})
      .activeWhen(on.key, on.values);
}

ElasticitySpec readElasticitySection(const Config& c) {
  ElasticitySpec e;
  const std::string model = c.getString("elasticity.model");
  if (model == "none") return e;
  e.enabled = true;
  e.model = parseFromConfig(c, solvers::elasticModels(), "elasticity.model");
  e.every = static_cast<std::size_t>(c.getInt("elasticity.every"));
  if (c.has("elasticity.by_property")) e.type_property = c.getString("elasticity.by_property");
  e.young = detail::readCoefficient(c, "elasticity", "young");
  e.poisson = detail::readCoefficient(c, "elasticity", "poisson");
  for (const auto& [type, nu] : e.poisson.by_type)
    if (!(nu < 0.5)) throw c.errorAt("elasticity.poisson_by", "Poisson's ratio must be < 0.5, got " + formatValue(nu));
  if (!(e.poisson.uniform < 0.5))
    throw c.errorAt("elasticity.poisson", "must be < 0.5, got " + formatValue(e.poisson.uniform));
  if (e.model != solvers::ElasticModel::Solid) e.thickness = c.getFloat("elasticity.thickness");
  for (const auto& [name, comps] : detail::parseNamedItems(c, "elasticity.fixed")) {
    std::array<bool, 3> fixed{false, false, false};
    for (char ch : comps) {
      if (ch < 'x' || ch > 'z')
        throw c.errorAt("elasticity.fixed", "'" + name + "=" + comps + "': components are letters among x, y, z");
      fixed[static_cast<std::size_t>(ch - 'x')] = true;
    }
    e.fixed.emplace_back(detail::parseRegion(c, "elasticity.fixed", name), fixed);
  }
  if (e.fixed.empty()) throw c.errorAt("elasticity.fixed", "names no region; the body would be free");
  const std::string stretch = c.getString("elasticity.stretch_region");
  if (stretch == "all") throw c.errorAt("elasticity.stretch_region", "'all' has no axis; choose a face such as x_max");
  if (stretch != "none") {
    e.stretch_region = detail::parseRegion(c, "elasticity.stretch_region", stretch);
    e.stretch = c.getFloat("elasticity.stretch");
  }
  const std::string traction = c.getString("elasticity.traction_region");
  if (traction != "none") {
    e.traction_region = detail::parseRegion(c, "elasticity.traction_region", traction);
    e.traction = c.getVec("elasticity.traction");
  }
  return e;
}

void addElasticityStage(const ElasticitySpec& e, StageList& stages) {
  if (e.enabled) stages.add(std::make_unique<ElasticityStage>(e, stages.fieldMesh()));
}

}  // namespace tessella::sim
