// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <cctype>
#include <cstdint>
#include <set>

#include "../stages/reaction_terms.hpp"
#include "coupling_values.hpp"
#include "tessella/sim/sections/coupling_section.hpp"

namespace tessella::sim {

namespace {
const std::vector<std::string> kOn = {"transient", "steady"};
const std::string kMap = "diffusion.species_map";

// The keys of one species, at `p` = "diffusion" (single-species form, not
// used when species_map is given) or "diffusion.species_map.<name>" (one
// entry of the several-species form).
void declareSpeciesKeys(Schema& s, const std::string& p, const Condition& on, bool single) {
  const std::string unless = single ? kMap : "";
  auto key = [&](const std::string& name, ValueType type, const std::string& doc) -> KeySpec& {
    return s.key(p + "." + name, type, doc).activeWhen(on.key, on.values).unlessSet(unless);
  };
  auto perType = [&](const std::string& name, const std::string& doc) {
    detail::declarePerTypeKey(s, p + "." + name, doc, on).unlessSet(unless);
  };
  key("initial", ValueType::Float, "Initial value everywhere.").byDefault(0.0).activeWhen("diffusion.mode", {"transient"});
  key("diffusivity", ValueType::Float, "Diffusivity D.").byDefault(1.0).atLeast(0);
  perType("diffusivity_by", "Diffusivity per cell type, e.g. \"0=1, 1=0.1\".");
  key("decay", ValueType::Float, "Linear decay rate k.").byDefault(0.0).atLeast(0);
  perType("decay_by", "Decay per cell type.");
  key("production", ValueType::Float, "Production p (per unit time) in every cell.").byDefault(0.0);
  perType("production_by", "Production per cell type.");
  detail::declareSourceKeys(s, p, on).unlessSet(unless);
  key("dirichlet", ValueType::String,
      "Fixed values on boundary regions, e.g. \"x_min=1, x_max=0\". Regions: all, x_min, x_max, "
      "y_min, y_max, z_min, z_max (boundary facets on that face of the bounding box). Where "
      "regions overlap, the later one wins.")
      .whenAbsent("none");
  key("flux", ValueType::String,
      "Influx (amount entering per unit boundary measure and time) on boundary regions, e.g. \"y_max=0.5\".")
      .whenAbsent("none (boundaries without a condition have zero flux)");
  key("robin", ValueType::String, "Exchange with the outside, -D du/dn = h (u - exterior), as region=h, e.g. \"all=0.2\".")
      .whenAbsent("none");
  key("exterior", ValueType::Float, "Exterior value of the Robin exchange.").byDefault(0.0);
  key("reaction", ValueType::String,
      single ? "Reaction rate r(u) added to du/dt: a muparser expression in the species name, e.g. "
               "\"u*(1-u)\" for species u. Explicit in time (docs/solvers.md)."
             : "Reaction rate added to this species' du/dt: a muparser expression in the names of all the "
               "species, e.g. \"A^2/B - A\". Explicit in time (docs/solvers.md).")
      .whenAbsent("no reaction");
}

/// The keys of the single-species form that do not apply to several species.
const std::vector<std::string> kPerSpecies = {
    "species",      "initial",    "diffusivity",   "diffusivity_by", "decay",    "decay_by", "production",
    "production_by", "dirichlet", "flux",          "robin",          "exterior", "reaction",
    "source.rate",   "source.center", "source.radius", "source.cells"};

SpeciesSpec readSpecies(const Config& c, const std::string& p, std::string name, bool steady) {
  SpeciesSpec sp;
  sp.name = std::move(name);
  sp.key_prefix = p;
  if (!steady) sp.initial = c.getFloat(p + ".initial");
  const std::string by = "diffusion.by_property";
  sp.diffusivity = detail::readCoefficient(c, p, "diffusivity", by);
  sp.decay = detail::readCoefficient(c, p, "decay", by);
  sp.production = detail::readCoefficient(c, p, "production", by);
  sp.source = detail::readSource(c, p);
  sp.dirichlet = detail::parseRegionValues(c, p + ".dirichlet");
  sp.flux = detail::parseRegionValues(c, p + ".flux");
  sp.robin = detail::parseRegionValues(c, p + ".robin");
  for (const RegionValue& r : sp.robin)
    if (r.value < 0)
      throw c.errorAt(p + ".robin", std::string("transfer coefficient of '") + boundaryRegionName(r.region) +
                                        "' must be >= 0, got " + formatValue(r.value));
  sp.robin_exterior = c.getFloat(p + ".exterior");
  if (c.has(p + ".reaction")) {
    sp.reaction = c.getString(p + ".reaction");
    if (sp.reaction.find_first_not_of(" \t") == std::string::npos)
      throw c.errorAt(p + ".reaction", "empty expression; leave the key out for no reaction");
  }
  if (steady && sp.dirichlet.empty() && sp.robin.empty() && sp.decay.uniform == 0.0 && sp.decay.by_type.empty())
    throw c.errorAt(p == "diffusion" ? "diffusion.mode" : p + ".decay",
                    "a steady state of species '" + sp.name +
                        "' needs a Dirichlet or Robin boundary condition or a decay; with zero-flux "
                        "boundaries and no decay it is defined only up to a constant");
  return sp;
}

// The single form's rule, as before several species: letters, digits, '_'
// (a leading digit is then refused by muparser if the name is used in a
// reaction; species_map entries are checked by the loader, no leading digit).
bool validName(const std::string& n) {
  if (n.empty()) return false;
  for (unsigned char ch : n)
    if (!(std::isalnum(ch) || ch == '_')) return false;
  return true;
}
}  // namespace

void declareDiffusionSection(Schema& s) {
  s.section("diffusion",
            "Species diffusing and reacting on the tissue's finite-element mesh (P1): du/dt = div(D grad u) "
            "- k u + p + r(species), with boundary conditions on parts of the tissue boundary. One species "
            "is given by the keys of this section; several by `species_map`, one entry per species, "
            "sharing the mesh, the solver and the keys mode, scheme, mass, every, dt and by_property. The "
            "mesh is rebuilt when the tissue changed (options of the mesh section) and each species is "
            "carried over conserving its total amount. Nodal values go to the mesh series, cell averages "
            "and amounts to the tissue as cell properties <species> and <species>_amount. Off unless "
            "`mode` is set. See docs/solvers.md.");
  s.key("diffusion.mode", ValueType::Enum,
        "`transient`: advance in time with the simulation; `steady`: solve the steady state at each solve.")
      .oneOf({"none", "transient", "steady"})
      .byDefault(std::string("none"));
  const Condition on{"diffusion.mode", kOn};
  s.key("diffusion.species", ValueType::String,
        "Name of the single species (letters, digits, '_'); names its outputs and its variable in "
        "`reaction`.")
      .byDefault(std::string("u"))
      .activeWhen(on.key, on.values)
      .unlessSet(kMap);
  s.key("diffusion.scheme", ValueType::Enum, "Time scheme: implicit Euler (order 1) or Crank-Nicolson (order 2).")
      .oneOf(solvers::timeSchemes().names())
      .byDefault(std::string("implicit_euler"))
      .activeWhen("diffusion.mode", {"transient"});
  s.key("diffusion.mass", ValueType::Enum,
        "Mass matrix: consistent (accurate) or lumped (keeps a positive solution positive on acute meshes).")
      .oneOf(solvers::massTypes().names())
      .byDefault(std::string("consistent"))
      .activeWhen(on.key, on.values);
  detail::declareEveryAndStep(s, "diffusion", on);
  s.key("diffusion.restart", ValueType::Enum,
        "A run restarted from a snapshot of a run (`tissue.generator: snapshot`): `continue` the mesh and "
        "nodal values saved beside the snapshot (<snapshot>.fields.vtu), so the restart ends as the "
        "uninterrupted run, bit for bit; a missing, damaged or mismatched file is an error naming it. "
        "`fresh`: start every species from `initial` on a new mesh instead.")
      .oneOf({"continue", "fresh"})
      .byDefault(std::string("continue"))
      .activeWhen(on.key, on.values);
  declareSpeciesKeys(s, "diffusion", on, true);
  s.section(kMap,
            "Several species in one stage: a map from each species' name (letters, digits, '_', not "
            "starting with a digit; it names the outputs and the species' variable in reaction "
            "expressions) to its keys. When given, the per-species keys of `diffusion` itself "
            "(species, initial, diffusivity, ..., reaction) must not be.")
      .activeWhen(on.key, on.values)
      .entryMap("species");
  s.section(kMap + "." + kEntryPlaceholder, "One species; every key is optional.");
  declareSpeciesKeys(s, kMap + "." + kEntryPlaceholder, on, false);
}

DiffusionSpec readDiffusionSection(const Config& c) {
  DiffusionSpec d;
  const std::string mode = c.getString("diffusion.mode");
  if (mode == "none") return d;
  d.steady = mode == "steady";
  if (!d.steady) d.scheme = parseFromConfig(c, solvers::timeSchemes(), "diffusion.scheme");
  d.mass = parseFromConfig(c, solvers::massTypes(), "diffusion.mass");
  d.every = static_cast<std::size_t>(c.getInt("diffusion.every"));
  if (c.has("diffusion.dt")) d.dt = c.getFloat("diffusion.dt");
  if (c.has("diffusion.by_property")) d.type_property = c.getString("diffusion.by_property");
  d.fresh_restart = c.getString("diffusion.restart") == "fresh";

  const std::vector<std::string> names = c.entryNames(kMap);
  if (names.empty()) {
    const std::string name = c.getString("diffusion.species");
    if (!validName(name))
      throw c.errorAt("diffusion.species", "must be a name of letters, digits and '_', got '" + name + "'");
    d.species.push_back(readSpecies(c, "diffusion", name, d.steady));
  } else {
    for (const std::string& key : kPerSpecies)
      if (c.isGiven("diffusion." + key))
        throw c.errorAt("diffusion." + key, "with diffusion.species_map, give it per species: " + kMap +
                                                "." + names.front() + "." + key);
    for (const std::string& name : names) d.species.push_back(readSpecies(c, kMap + "." + name, name, d.steady));
  }

  // Each species writes the cell properties <name>, <name>_amount and <name>_source.
  std::set<std::string> outputs;
  for (const SpeciesSpec& sp : d.species)
    for (const std::string& out : {sp.name, sp.name + "_amount", sp.name + "_source"})
      if (!outputs.insert(out).second)
        throw ConfigError(c.entryLocation(sp.key_prefix), sp.key_prefix,
                          "species '" + sp.name + "' would write the cell property '" + out +
                              "', which another species writes; choose another name");

  // Reaction expressions compile now, so a bad one is an error at its key.
  std::vector<std::string> all, expressions, keys;
  for (const SpeciesSpec& sp : d.species) {
    all.push_back(sp.name);
    expressions.push_back(sp.reaction);
    keys.push_back(sp.key_prefix + ".reaction");
  }
  if (d.hasReaction()) {
    try {
      detail::ReactionTerms check(all, expressions, keys);
    } catch (const detail::ReactionExpressionError& e) {
      throw c.errorAt(d.species[e.species()].key_prefix + ".reaction", e.what());
    }
  }
  return d;
}

void addDiffusionStage(const DiffusionSpec& d, StageList& stages) {
  if (!d.species.empty()) stages.add(std::make_unique<DiffusionStage>(d, stages.fieldMesh()));
}

}  // namespace tessella::sim
