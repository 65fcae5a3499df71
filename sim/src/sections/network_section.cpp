// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/network_section.hpp"

#include <set>
#include <sstream>

#include "coupling_values.hpp"
#include "tessella/networks/initial_values.hpp"
#include "tessella/networks/pin_expression.hpp"
#include "tessella/networks/reaction_set.hpp"
#include "tessella/sim/config/registry_config.hpp"
#include "tessella/sim/sections/section_unit.hpp"

namespace tessella::sim {

namespace {
const std::string kSpecies = "network.species";

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}
}  // namespace

void declareNetworkSection(Schema& s) {
  s.section("network",
            "A cell-level regulatory network: species in every cell with reactions (muparser expressions), "
            "passive exchange across walls and PIN-mediated efflux with up-the-gradient polarity, integrated "
            "by CVODE (BDF, sparse Newton with KLU) over each solve interval. The amount of each species is the "
            "cell property <species>_amount (split by measure at division: conserved), its concentration "
            "<species>; with PIN transport each cell's polarity (PIN-weighted sum of outward wall normals) is "
            "the vector cell property <species>_polarity. Off unless `mode` is set. See docs/networks.md.");
  s.key("network.mode", ValueType::Enum, "`transient`: advance in time with the simulation.")
      .oneOf({"none", "transient"})
      .byDefault(std::string("none"));
  const Condition on{"network.mode", {"transient"}};
  auto key = [&](const std::string& path, ValueType type, const std::string& doc) -> KeySpec& {
    return s.key(path, type, doc).activeWhen(on.key, on.values);
  };
  key("network.every", ValueType::Int, "Integrate every `every` steps, over the time since the previous solve.")
      .byDefault(std::int64_t{1})
      .atLeast(1);
  key("network.relative_tolerance", ValueType::Float, "CVODE's relative tolerance.").byDefault(1e-6).above(0);
  key("network.absolute_tolerance", ValueType::Float, "CVODE's absolute tolerance, on amounts.")
      .byDefault(1e-9)
      .above(0);
  key("network.max_steps", ValueType::Int, "Most internal CVODE steps per solve interval.")
      .byDefault(std::int64_t{100000})
      .atLeast(1);
  key("network.jacobian", ValueType::Enum,
      "The Jacobian of CVODE's Newton iteration: `exact`, or `neighbours` (without the second-neighbour terms "
      "of PIN transport: a sparser matrix, cheaper to factorise; an approximation that changes the work, not "
      "the accuracy, which the tolerances control).")
      .oneOf(networks::jacobianKinds().names())
      .byDefault(std::string("exact"));
  key("network.linear_solver", ValueType::Enum,
      "The linear solver of CVODE's Newton iteration: `klu` (sparse LU, exact solves) or `gmres` (GMRES with a "
      "block-Jacobi preconditioner per cell: much faster on large tissues; the same tolerances).")
      .oneOf(networks::linearSolvers().names())
      .byDefault(std::string("klu"));
  key("network.parameters", ValueType::String,
      "Named constants of the reactions and initial values, \"name=value, ...\", e.g. \"p=1, d=0.1\".")
      .whenAbsent("none");
  key("network.properties", ValueType::String,
      "Cell properties (double or int) the reactions read, \"name, name\" (their values at the start of each "
      "solve; e.g. primordium, the id network.primordia writes).")
      .whenAbsent("none");
  s.section(kSpecies,
            "The species: a map from each species' name (letters, digits, '_', not starting with a digit; it "
            "names its cell properties and its variable in reactions) to its keys.")
      .activeWhen(on.key, on.values)
      .entryMap("species");
  const std::string e = kSpecies + "." + kEntryPlaceholder;
  s.section(e, "One species; every key is optional.");
  s.key(e + ".initial", ValueType::String,
        "Initial concentration: a number or an expression over x, y, z (the cell's centroid), measure and the "
        "parameters, e.g. \"1 + 0.1 * x\".")
      .byDefault(std::string("0"));
  s.key(e + ".noise", ValueType::Float,
        "Amplitude of uniform noise added to the initial concentration (a draw in [0, noise) per cell, from "
        "a stream seeded by the run's rng_seed).")
      .byDefault(0.0)
      .atLeast(0);
  s.key(e + ".reaction", ValueType::String,
        "Rate of change of the concentration inside a cell: a muparser expression over the species, the "
        "parameters, the properties named in network.properties, measure, x, y, z, t and the neighbourhood "
        "terms sum_<species> (sum over the neighbours j of L_ij c_j, L_ij the interface's length or area) and "
        "mean_<species> (the same divided by sum_j L_ij), e.g. \"p - d * auxin\" or \"k * (mean_auxin - auxin)\".")
      .whenAbsent("no reaction");
  s.key(e + ".permeability", ValueType::Float,
        "Passive permeability P: a wall of length (2D) or area (3D) L between cells i and j carries "
        "P L (c_i - c_j) of amount per unit time.")
      .byDefault(0.0)
      .atLeast(0);
  s.section("network.pin",
            "Carrier-mediated efflux of one species by PIN. up_the_gradient: PIN_ij = P_i L_ij f(c_j) / "
            "(saturation + sum_k L_ik f(c_k)) on cell i's side of its wall to neighbour j, P_i = total + "
            "total_per_concentration c_i, and the efflux from i into j is rate PIN_ij g(c_i), g(c) = c (efflux: "
            "linear) or c^2 / (1 + efflux_saturation c^2) (efflux: saturating, Smith et al. 2006). with_the_flux and "
            "expression: the PIN density p_ij on each wall side is a "
            "state, dp_ij/dt = (basal + production h(phi_ij)) B_i - decay p_ij (h(phi) = phi^m / (1 + s phi^m) "
            "for a net flux density phi > 0 from i into j, else 0; B_i = 1 - sum_k L_ik p_ik / total when "
            "bounded, else 1) or the user's expression, and the efflux from i into j is rate L_ij p_ij c_i; the "
            "densities are the wall properties <species>_pin_pos / _pin_neg and the snapshot's run state "
            "network.pin (docs/networks.md).")
      .activeWhen(on.key, on.values);
  s.key("network.pin.species", ValueType::String, "The transported species.").whenAbsent("no PIN transport");
  s.key("network.pin.model", ValueType::Enum, "How PIN is allocated to the walls.")
      .oneOf(networks::pinModels().names())
      .byDefault(std::string("up_the_gradient"));
  s.key("network.pin.function", ValueType::Enum,
        "The weight f of a neighbour's concentration: exponential f(c) = base^c, power f(c) = c^exponent.")
      .oneOf(networks::pinFunctions().names())
      .byDefault(std::string("exponential"));
  s.key("network.pin.base", ValueType::Float, "b of f(c) = b^c.").byDefault(3.0).above(0);
  s.key("network.pin.exponent", ValueType::Float, "n of f(c) = c^n.").byDefault(1.0).above(0);
  s.key("network.pin.rate", ValueType::Float, "T: efflux per unit PIN and unit concentration.")
      .byDefault(1.0)
      .atLeast(0);
  s.key("network.pin.total", ValueType::Float,
        "up_the_gradient: PIN per cell (P_i = total + total_per_concentration c_i); with_the_flux: the bound of a "
        "cell's PIN when bounded.")
      .byDefault(1.0)
      .atLeast(0);
  s.key("network.pin.total_per_concentration", ValueType::Float,
        "up_the_gradient: PIN made in proportion to the transported species, P_i = total + "
        "total_per_concentration c_i (Smith et al. 2006, PIN production at its steady state).")
      .byDefault(0.0)
      .atLeast(0);
  s.key("network.pin.efflux", ValueType::Enum,
        "up_the_gradient: g(c_i) of the efflux rate PIN_ij g(c_i): linear g = c, saturating g = c^2 / (1 + "
        "efflux_saturation c^2) (Smith et al. 2006).")
      .oneOf(networks::pinEffluxes().names())
      .byDefault(std::string("linear"));
  s.key("network.pin.efflux_saturation", ValueType::Float,
        "up_the_gradient with efflux: saturating: s of g(c) = c^2 / (1 + s c^2).")
      .byDefault(0.0)
      .atLeast(0);
  s.key("network.pin.saturation", ValueType::Float, "kappa: added to the denominator, in units of wall measure.")
      .byDefault(0.0)
      .atLeast(0);
  s.key("network.pin.initial", ValueType::Float,
        "with_the_flux, expression: the PIN density on every wall side at the start and on each new wall.")
      .byDefault(0.0)
      .atLeast(0);
  s.key("network.pin.basal", ValueType::Float, "with_the_flux: rho_0, PIN density made per unit time without flux.")
      .byDefault(0.0)
      .atLeast(0);
  s.key("network.pin.production", ValueType::Float, "with_the_flux: rho, PIN density made per unit time and unit h.")
      .byDefault(1.0)
      .atLeast(0);
  s.key("network.pin.decay", ValueType::Float, "with_the_flux: mu, the PIN density decays at mu p.")
      .byDefault(1.0)
      .atLeast(0);
  s.key("network.pin.flux_exponent", ValueType::Float, "with_the_flux: m of h(phi) = phi^m / (1 + s phi^m).")
      .byDefault(2.0)
      .atLeast(1);
  s.key("network.pin.flux_saturation", ValueType::Float, "with_the_flux: s of h(phi) (0: no saturation).")
      .byDefault(0.0)
      .atLeast(0);
  s.key("network.pin.bounded", ValueType::Bool,
        "with_the_flux: production times 1 - (PIN on the cell's walls) / total, so a cell's PIN stays below "
        "`total`.")
      .byDefault(false);
  s.key("network.pin.expression", ValueType::String,
        "expression: dp_ij/dt, a muparser expression over c_i, c_j (the species in the cell and its neighbour), "
        "pin (p_ij), pin_opposite (p_ji), flux (net flux density from i into j), wall (L_ij), measure (V_i), "
        "pin_cell (sum_k L_ik p_ik), t and the parameters.")
      .whenAbsent("required with model: expression");
  s.section("network.primordia",
            "Primordium detection after each solve: a cell whose concentration of `species` is above `threshold` "
            "and above every neighbour's, at a distance from the apex in [min_radius, max_radius] and at "
            "least min_separation from every existing primordium, starts a new one: its id goes to the int cell "
            "property `primordium` (copied to daughters) and a row to <output directory>/primordia.csv (time, "
            "lineage id, position, angle about the axis, distances from the axis and the apex, divergence from the "
            "previous one). "
            "docs/networks.md, \"Phyllotaxis on a growing dome\".")
      .activeWhen(on.key, on.values);
  s.key("network.primordia.species", ValueType::String, "The species whose peaks are primordia (e.g. auxin).")
      .whenAbsent("no primordium detection");
  s.key("network.primordia.threshold", ValueType::Float,
        "Concentration a peak must exceed; required with `species`.")
      .whenAbsent("required with species");
  s.key("network.primordia.min_radius", ValueType::Float,
        "Inner radius of the peripheral annulus: straight-line distance from the apex (not along the "
        "surface, not from the axis: cells that flowed past the dome's base come closer to the axis again).")
      .byDefault(0.0)
      .atLeast(0);
  s.key("network.primordia.max_radius", ValueType::Float, "Outer radius of the peripheral annulus.")
      .whenAbsent("no outer limit");
  s.key("network.primordia.min_separation", ValueType::Float,
        "Least distance (straight line) of a new primordium's cell from every existing primordium, whose "
        "position is the mean centroid of the cells carrying its id.")
      .byDefault(0.0)
      .atLeast(0);
  s.key("network.primordia.apex", ValueType::Vec3, "A point on the dome's axis (its summit).")
      .byDefault(std::vector<double>{0, 0, 0});
  s.key("network.primordia.axis", ValueType::Vec3,
        "The dome's axis; angles are counterclockwise about it from the x axis projected on its normal plane.")
      .byDefault(std::vector<double>{0, 0, 1});
}

NetworkSpec readNetworkSection(const Config& c, std::uint64_t noise_seed) {
  NetworkSpec n;
  if (c.getString("network.mode") == "none") return n;
  n.noise_seed = noise_seed;
  n.every = static_cast<std::size_t>(c.getInt("network.every"));
  n.integrator.relative_tolerance = c.getFloat("network.relative_tolerance");
  n.integrator.absolute_tolerance = c.getFloat("network.absolute_tolerance");
  n.integrator.max_steps = static_cast<long>(c.getInt("network.max_steps"));
  n.jacobian = parseFromConfig(c, networks::jacobianKinds(), "network.jacobian");
  n.integrator.linear_solver = parseFromConfig(c, networks::linearSolvers(), "network.linear_solver");
  networks::NetworkModel& m = n.model;
  if (c.has("network.parameters"))
    for (const auto& [name, value] : detail::parseNamedItems(c, "network.parameters"))
      m.parameters[name] = detail::parseNumber(c, "network.parameters", name, value);
  if (c.has("network.properties")) {
    std::stringstream all(c.getString("network.properties"));
    std::string item;
    while (std::getline(all, item, ',')) {
      item = trimmed(item);
      if (!item.empty()) m.cell_properties.push_back(item);
    }
  }
  const std::vector<std::string> names = c.entryNames(kSpecies);
  if (names.empty()) throw c.errorAt("network.mode", "a network needs species: give " + kSpecies + ".<name>");
  for (const std::string& name : names) {
    const std::string p = kSpecies + "." + name;
    networks::NetworkSpecies sp;
    sp.name = name;
    sp.permeability = c.getFloat(p + ".permeability");
    if (c.has(p + ".reaction")) {
      sp.reaction = c.getString(p + ".reaction");
      if (trimmed(sp.reaction).empty())
        throw c.errorAt(p + ".reaction", "empty expression; leave the key out for no reaction");
    }
    m.species.push_back(sp);
    n.initial.push_back(c.getString(p + ".initial"));
    n.noise.push_back(c.getFloat(p + ".noise"));
  }
  if (c.has("network.pin.species")) {
    m.pin.species = c.getString("network.pin.species");
    if (m.speciesIndex(m.pin.species) < 0) {
      std::string known;
      for (const auto& s : m.species) known += (known.empty() ? "" : ", ") + s.name;
      throw c.errorAt("network.pin.species", "'" + m.pin.species + "' is not a species (species: " + known + ")");
    }
    m.pin.model = parseFromConfig(c, networks::pinModels(), "network.pin.model");
    m.pin.function = parseFromConfig(c, networks::pinFunctions(), "network.pin.function");
    m.pin.base = c.getFloat("network.pin.base");
    m.pin.exponent = c.getFloat("network.pin.exponent");
    m.pin.rate = c.getFloat("network.pin.rate");
    m.pin.total = c.getFloat("network.pin.total");
    m.pin.saturation = c.getFloat("network.pin.saturation");
    m.pin.total_per_concentration = c.getFloat("network.pin.total_per_concentration");
    m.pin.efflux = parseFromConfig(c, networks::pinEffluxes(), "network.pin.efflux");
    m.pin.efflux_saturation = c.getFloat("network.pin.efflux_saturation");
    m.pin.initial = c.getFloat("network.pin.initial");
    m.pin.basal = c.getFloat("network.pin.basal");
    m.pin.production = c.getFloat("network.pin.production");
    m.pin.decay = c.getFloat("network.pin.decay");
    m.pin.flux_exponent = c.getFloat("network.pin.flux_exponent");
    m.pin.flux_saturation = c.getFloat("network.pin.flux_saturation");
    m.pin.bounded = c.getBool("network.pin.bounded");
    if (c.has("network.pin.expression")) m.pin.expression = c.getString("network.pin.expression");
    if (m.pin.model == networks::PinModel::Expression && trimmed(m.pin.expression).empty())
      throw c.errorAt("network.pin.model", "the PIN model 'expression' needs network.pin.expression (dp_ij/dt)");
    if (m.pin.bounded && !(m.pin.total > 0))
      throw c.errorAt("network.pin.bounded", "bounded PIN needs network.pin.total > 0");
  }
  if (c.has("network.primordia.species")) {
    PrimordiaSpec& pr = n.primordia;
    pr.species = c.getString("network.primordia.species");
    if (m.speciesIndex(pr.species) < 0) throw c.errorAt("network.primordia.species", "'" + pr.species +
                                                        "' is not a species of network.species");
    if (!c.has("network.primordia.threshold"))
      throw c.errorAt("network.primordia.species", "primordium detection needs network.primordia.threshold");
    networks::PrimordiumOptions& o = pr.options;
    o.threshold = c.getFloat("network.primordia.threshold");
    o.min_radius = c.getFloat("network.primordia.min_radius");
    if (c.has("network.primordia.max_radius")) o.max_radius = c.getFloat("network.primordia.max_radius");
    o.min_separation = c.getFloat("network.primordia.min_separation");
    o.apex = c.getVec("network.primordia.apex");
    o.axis = c.getVec("network.primordia.axis");
    try {
      o.validate();
    } catch (const InputError& e) {
      throw c.errorAt(o.axis.norm() > 0 ? "network.primordia.max_radius" : "network.primordia.axis", e.what());
    }
  }
  // Names: a parameter or property that clashes with a species or a reserved name.
  try {
    m.validate();
  } catch (const InputError& e) {
    throw c.errorAt(c.has("network.parameters") ? "network.parameters" : "network.mode", e.what());
  }
  if (m.pin.model == networks::PinModel::Expression && m.pin.enabled()) {
    try {
      networks::PinExpression check(m);
    } catch (const InputError& e) {
      throw c.errorAt("network.pin.expression", e.what());
    }
  }
  // Each reaction and initial value compiles now, so a bad one is an error at its key.
  for (std::size_t s = 0; s < m.species.size(); ++s) {
    const std::string p = kSpecies + "." + m.species[s].name;
    if (!m.species[s].reaction.empty()) {
      networks::NetworkModel one = m;
      for (std::size_t q = 0; q < one.species.size(); ++q)
        if (q != s) one.species[q].reaction.clear();
      try {
        networks::ReactionSet check(one);
      } catch (const InputError& e) {
        throw c.errorAt(p + ".reaction", e.what());
      }
    }
    try {
      networks::checkInitialExpression(n.initial[s], m.parameters);
    } catch (const InputError& e) {
      throw c.errorAt(p + ".initial", e.what());
    }
  }
  return n;
}

void addNetworkStage(const NetworkSpec& network, StageList& stages) {
  if (network.enabled()) stages.add(std::make_unique<NetworkStage>(network));
}

}  // namespace tessella::sim
