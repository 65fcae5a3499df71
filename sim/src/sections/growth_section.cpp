// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/growth_section.hpp"

#include <algorithm>
#include <string>

#include "tessella/growth/registries.hpp"
#include "tessella/growth/surface_projection.hpp"
#include "tessella/sim/config/registry_config.hpp"
#include "tessella/tissue/errors.hpp"

// The keys of the velocity fields, surfaces, division rules and thresholds,
// their choices and their docs come from growth/'s tables (registries.hpp):
// a new field or rule needs no edit here.

namespace tessella::sim {

void declareGrowthSection(Schema& s) {
  const auto& fields = growth::velocityFields();
  const auto& surfaces = growth::surfaces();
  s.section("growth",
            "Growth: every step, the vertices move with a velocity field (the PlantGL paper's "
            "kinematic growth). Off unless `field` is set. See docs/growth.md.");
  s.key("growth.field", ValueType::Enum,
        "The velocity field; each field reads the keys of its section below (`growth.<field>`).")
      .oneOf(withNone(fields.names()))
      .byDefault(std::string("none"));
  s.key("growth.scheme", ValueType::Enum, "Time integration. " + choicesDoc(growth::integrationSchemes()))
      .oneOf(growth::integrationSchemes().names())
      .byDefault(std::string("heun"));
  s.key("growth.velocities", ValueType::Enum,
        "Which vertices the field moves. " + choicesDoc(growth::velocitySources()))
      .oneOf(growth::velocitySources().names())
      .byDefault(std::string("field"));
  s.key("growth.surface", ValueType::Enum,
        "Keep a curved-sheet tissue on a surface after every stage (planar tissues always stay at z = 0). " +
            choicesDoc(surfaces))
      .oneOf(withNone(surfaces.names()))
      .byDefault(std::string("none"));
  s.key("growth.check_inversion", ValueType::Bool,
        "Stop with an error naming the cell and time when a step inverts or collapses a cell "
        "(lower dt); off lets inverted cells through. A non-finite velocity or position is an error "
        "either way.")
      .byDefault(true);
  declareEntrySections(s, "growth", "growth.field", fields);
  declareEntrySections(s, "growth", "growth.surface", surfaces);
}

void declareDivisionSection(Schema& s) {
  const auto& rules = growth::divisionRules();
  const auto& thresholds = growth::divisionThresholds();
  s.section("division",
            "Division: every step, cells whose size (area in 2D, volume in 3D) exceeds their "
            "threshold divide by the plane the rule chooses. Off unless `rule` is set. See "
            "docs/growth.md.");
  s.key("division.rule", ValueType::Enum, "Where cells divide. " + choicesDoc(rules))
      .oneOf(withNone(rules.names()))
      .byDefault(std::string("none"));
  s.key("division.threshold", ValueType::Enum, "The size threshold. " + choicesDoc(thresholds))
      .oneOf(thresholds.names())
      .byDefault(std::string("fixed"))
      .activeWhen("division.rule", rules.names());
  declareEntryKeys(s, "division", "division.threshold", thresholds);
  declareEntryKeys(s, "division", "division.rule", rules);
  s.key("division.max_attempts", ValueType::Int,
        "Planes tried per cell when a cut is degenerate (the rule's, then slightly rotated and "
        "shifted ones); after that the cell waits for the next step.")
      .byDefault(std::int64_t{5})
      .atLeast(1)
      .atMost(100)
      .activeWhen("division.rule", rules.names());
  s.section("division.gate",
            "Division gated by a field: a cell over its size threshold divides only if the cell "
            "average of `field` (a diffusion species or compartment field, or another cell property "
            "the solver sections write) exceeds `above`. Before the field's first solve no cell divides.")
      .activeWhen("division.rule", rules.names());
  s.key("division.gate.field", ValueType::String, "The gating field (e.g. the diffusion species' name).")
      .whenAbsent("no gate");
  s.key("division.gate.above", ValueType::Float, "Cells divide only where the field is above this value.")
      .byDefault(0.0);
}

GrowthSpec readGrowthSection(const Config& c, const TissueSpec& tissue) {
  GrowthSpec g;
  g.options.scheme = parseFromConfig(c, growth::integrationSchemes(), "growth.scheme");
  g.options.source = parseFromConfig(c, growth::velocitySources(), "growth.velocities");
  g.options.check_inversion = c.getBool("growth.check_inversion");
  const std::string surface = c.getString("growth.surface");
  if (surface != "none") {
    // The surface the tissue was built on, for surface: dome.
    const std::optional<Dome> dome = tissueDome(tissue);
    const growth::SurfaceProjection own = dome ? growth::domeProjection(*dome) : growth::SurfaceProjection{};
    g.options.projection =
        makeFromConfig(c, growth::surfaces(), surface, "growth." + surface, "growth.surface", own);
  }
  const std::string field = c.getString("growth.field");
  if (field != "none") g.field = makeFromConfig(c, growth::velocityFields(), field, "growth." + field, "growth.field");
  return g;
}

DivisionSpec readDivisionSection(const Config& c) {
  DivisionSpec d;
  const std::string rule = c.getString("division.rule");
  if (rule == "none") return d;
  d.rule = makeFromConfig(c, growth::divisionRules(), rule, "division", "division.rule");
  d.threshold = makeFromConfig(c, growth::divisionThresholds(), c.getString("division.threshold"), "division",
                               "division.threshold");
  d.options.max_attempts = static_cast<int>(c.getInt("division.max_attempts"));
  if (c.has("division.gate.field"))
    d.gate = DivisionGate{.field = c.getString("division.gate.field"), .above = c.getFloat("division.gate.above")};
  return d;
}

void addGrowthStage(const GrowthSpec& g, StageList& stages) {
  if (g.field) stages.add(std::make_unique<GrowthStage>(g.field, g.options));
}

void addDivisionStage(const DivisionSpec& d, StageList& stages) {
  if (d.rule) stages.add(std::make_unique<DivisionStage>(d.rule, *d.threshold, d.options, d.gate));
}

void checkDivisionGate(const Config& c, const DivisionSpec& d, const std::vector<std::string>& fields) {
  if (!d.gate || !d.rule) return;
  if (std::find(fields.begin(), fields.end(), d.gate->field) != fields.end()) return;
  std::string known;
  for (const auto& f : fields) known += (known.empty() ? "" : ", ") + f;
  throw c.errorAt("division.gate.field", "'" + d.gate->field + "' is not a field of the solver sections" +
                                             (known.empty() ? std::string(" (none is on)") : " (known: " + known + ")"));
}

}  // namespace tessella::sim
