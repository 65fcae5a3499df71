// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "coupling_values.hpp"
#include "tessella/sim/sections/coupling_section.hpp"
#include "tessella/tissue/excerpt.hpp"

namespace tessella::sim {

namespace {
// One lineage id per line; '#' starts a comment; blank lines are skipped.
std::vector<std::int64_t> readCellFile(const Config& c, const std::string& key) {
  const std::string& path = c.getString(key);
  std::ifstream in(path);
  if (!in) throw c.errorAt(key, "cannot open '" + path + "'");
  std::vector<std::int64_t> ids;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    std::string token, extra;
    if (!(fields >> token)) continue;
    std::size_t used = 0;
    long long v = -1;
    try {
      v = std::stoll(token, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != token.size() || v < 0 || (fields >> extra))
      throw c.errorAt(key, path + ":" + std::to_string(number) + ": expected one lineage id (an integer >= 0) per "
                                  "line, got '" + excerpt(line) + "'");
    ids.push_back(v);
  }
  if (ids.empty()) throw c.errorAt(key, "'" + path + "' lists no cells");
  return ids;
}
}  // namespace

void declareCompartmentSection(Schema& s) {
  s.section("compartments",
            "Compartment transport: one well-mixed concentration per cell, exchanged across walls by "
            "passive permeability and polar (active) transport, with decay and production. The amount "
            "of each cell is the cell property <field>_amount, split between daughters by volume at "
            "division (conserved exactly); <field> holds the concentration. Off unless `mode` is set. "
            "See docs/solvers.md.");
  s.key("compartments.mode", ValueType::Enum, "`transient`: advance in time with the simulation.")
      .oneOf({"none", "transient"})
      .byDefault(std::string("none"));
  const Condition on{"compartments.mode", {"transient"}};
  s.key("compartments.field", ValueType::String, "Name of the concentration (letters, digits, '_').")
      .byDefault(std::string("c"))
      .activeWhen(on.key, on.values);
  s.key("compartments.scheme", ValueType::Enum, "Time scheme.")
      .oneOf(solvers::timeSchemes().names())
      .byDefault(std::string("implicit_euler"))
      .activeWhen(on.key, on.values);
  detail::declareEveryAndStep(s, "compartments", on);
  s.key("compartments.initial", ValueType::Float, "Initial concentration in every cell.")
      .byDefault(0.0)
      .atLeast(0)
      .activeWhen(on.key, on.values);
  s.key("compartments.permeability", ValueType::Float, "Passive permeability P of the walls (symmetric).")
      .byDefault(1.0)
      .atLeast(0)
      .activeWhen(on.key, on.values);
  detail::declarePerTypeKey(s, "compartments.permeability_by", "Permeability per cell type; a wall takes the smaller value of its two cells.", on);
  s.key("compartments.decay", ValueType::Float, "Decay rate k.").byDefault(0.0).atLeast(0).activeWhen(on.key, on.values);
  detail::declarePerTypeKey(s, "compartments.decay_by", "Decay per cell type.", on);
  s.key("compartments.production", ValueType::Float, "Production p (concentration per unit time).")
      .byDefault(0.0)
      .activeWhen(on.key, on.values);
  detail::declarePerTypeKey(s, "compartments.production_by", "Production per cell type.", on);
  detail::declareSourceKeys(s, "compartments", on);
  s.section("compartments.polar",
            "Polar transport: a pumping cell moves rate * wall area * its concentration per unit time "
            "across each wall to a neighbour whose centroid is downstream along `direction`. Superseded by "
            "`network:` with PIN transport (polarity from the tissue's state, docs/networks.md); kept for "
            "existing configs.")
      .activeWhen(on.key, on.values);
  s.key("compartments.polar.rate", ValueType::Float, "Pumping rate (per unit wall area).").byDefault(0.0).atLeast(0);
  s.key("compartments.polar.direction", ValueType::Vec3, "Direction of the pumping.")
      .byDefault(std::vector<double>{1, 0, 0});
  s.key("compartments.polar.cells", ValueType::Path,
        "File of the pumping cells: one lineage id per line ('#' comments). Marked with the cell "
        "property <field>_polar at the first solve; daughters inherit it.")
      .whenAbsent("every cell pumps");
}

CompartmentSpec readCompartmentSection(const Config& c) {
  CompartmentSpec d;
  if (c.getString("compartments.mode") == "none") return d;
  d.field = c.getString("compartments.field");
  const bool plain = !d.field.empty() && std::all_of(d.field.begin(), d.field.end(), [](unsigned char ch) {
    return std::isalnum(ch) || ch == '_';
  });
  if (!plain) throw c.errorAt("compartments.field", "must be a name of letters, digits and '_', got '" + d.field + "'");
  d.scheme = parseFromConfig(c, solvers::timeSchemes(), "compartments.scheme");
  d.every = static_cast<std::size_t>(c.getInt("compartments.every"));
  if (c.has("compartments.dt")) d.dt = c.getFloat("compartments.dt");
  d.initial = c.getFloat("compartments.initial");
  if (c.has("compartments.by_property")) d.type_property = c.getString("compartments.by_property");
  d.permeability = detail::readCoefficient(c, "compartments", "permeability");
  d.decay = detail::readCoefficient(c, "compartments", "decay");
  d.production = detail::readCoefficient(c, "compartments", "production");
  d.source = detail::readSource(c, "compartments");
  d.polar_rate = c.getFloat("compartments.polar.rate");
  d.polar_direction = c.getVec("compartments.polar.direction");
  if (d.polar_rate > 0 && !(d.polar_direction.norm() > 0))
    throw c.errorAt("compartments.polar.direction", "must be a non-zero vector");
  if (d.polar_rate > 0) d.polar_direction.normalize();
  if (c.has("compartments.polar.cells")) {
    d.polar_cells = readCellFile(c, "compartments.polar.cells");
    d.polar_all = false;
  }
  return d;
}

void addCompartmentStage(const CompartmentSpec& k, StageList& stages) {
  if (!k.field.empty()) stages.add(std::make_unique<CompartmentStage>(k));
}

}  // namespace tessella::sim
