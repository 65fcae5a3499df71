#include <cctype>
#include <cstdint>

#include "coupling_values.hpp"
#include "tessella/sim/coupling_section.hpp"

namespace tessella::sim {

namespace {
const std::vector<std::string> kOn = {"transient", "steady"};

bool validName(const std::string& n) {
  if (n.empty()) return false;
  for (unsigned char ch : n)
    if (!(std::isalnum(ch) || ch == '_')) return false;
  return true;
}
}  // namespace

void declareDiffusionSection(Schema& s) {
  s.section("diffusion",
            "A species diffusing on the tissue's finite-element mesh (P1): du/dt = div(D grad u) - k u "
            "+ p, with boundary conditions on parts of the tissue boundary. The mesh is rebuilt when the "
            "tissue changed (options of the mesh section) and u is carried over conserving its total "
            "amount. Nodal values go to the mesh series, cell averages and amounts to the tissue as "
            "cell properties <species> and <species>_amount. Off unless `mode` is set. See "
            "docs/solvers.md.");
  s.key("diffusion.mode", ValueType::Enum,
        "`transient`: advance in time with the simulation; `steady`: solve the steady state at each solve.")
      .oneOf({"none", "transient", "steady"})
      .byDefault(std::string("none"));
  const Condition on{"diffusion.mode", kOn};
  s.key("diffusion.species", ValueType::String, "Name of the species (letters, digits, '_'); names its outputs.")
      .byDefault(std::string("u"))
      .activeWhen(on.key, on.values);
  s.key("diffusion.scheme", ValueType::Enum, "Time scheme: implicit Euler (order 1) or Crank-Nicolson (order 2).")
      .oneOf({"implicit_euler", "crank_nicolson"})
      .byDefault(std::string("implicit_euler"))
      .activeWhen("diffusion.mode", {"transient"});
  s.key("diffusion.mass", ValueType::Enum,
        "Mass matrix: consistent (accurate) or lumped (keeps a positive solution positive on acute meshes).")
      .oneOf({"consistent", "lumped"})
      .byDefault(std::string("consistent"))
      .activeWhen(on.key, on.values);
  detail::declareEveryAndStep(s, "diffusion", on);
  s.key("diffusion.initial", ValueType::Float, "Initial value everywhere.")
      .byDefault(0.0)
      .activeWhen("diffusion.mode", {"transient"});
  s.key("diffusion.diffusivity", ValueType::Float, "Diffusivity D.").byDefault(1.0).atLeast(0).activeWhen(on.key, on.values);
  detail::declarePerTypeKey(s, "diffusion.diffusivity_by", "Diffusivity per cell type, e.g. \"0=1, 1=0.1\".", on);
  s.key("diffusion.decay", ValueType::Float, "Linear decay rate k.").byDefault(0.0).atLeast(0).activeWhen(on.key, on.values);
  detail::declarePerTypeKey(s, "diffusion.decay_by", "Decay per cell type.", on);
  s.key("diffusion.production", ValueType::Float, "Production p (per unit time) in every cell.")
      .byDefault(0.0)
      .activeWhen(on.key, on.values);
  detail::declarePerTypeKey(s, "diffusion.production_by", "Production per cell type.", on);
  detail::declareSourceKeys(s, "diffusion", on);
  s.key("diffusion.dirichlet", ValueType::String,
        "Fixed values on boundary regions, e.g. \"x_min=1, x_max=0\". Regions: all, x_min, x_max, "
        "y_min, y_max, z_min, z_max (boundary facets on that face of the bounding box). Where "
        "regions overlap, the later one wins.")
      .whenAbsent("none")
      .activeWhen(on.key, on.values);
  s.key("diffusion.flux", ValueType::String,
        "Influx (amount entering per unit boundary measure and time) on boundary regions, e.g. \"y_max=0.5\".")
      .whenAbsent("none (boundaries without a condition have zero flux)")
      .activeWhen(on.key, on.values);
  s.key("diffusion.robin", ValueType::String,
        "Exchange with the outside, -D du/dn = h (u - exterior), as region=h, e.g. \"all=0.2\".")
      .whenAbsent("none")
      .activeWhen(on.key, on.values);
  s.key("diffusion.exterior", ValueType::Float, "Exterior value of the Robin exchange.")
      .byDefault(0.0)
      .activeWhen(on.key, on.values);
}

DiffusionSpec readDiffusionSection(const Config& c) {
  DiffusionSpec d;
  const std::string mode = c.getString("diffusion.mode");
  if (mode == "none") return d;
  d.species = c.getString("diffusion.species");
  if (!validName(d.species))
    throw c.errorAt("diffusion.species", "must be a name of letters, digits and '_', got '" + d.species + "'");
  d.steady = mode == "steady";
  if (!d.steady && c.getString("diffusion.scheme") == "crank_nicolson") d.scheme = TimeScheme::CrankNicolson;
  d.mass = c.getString("diffusion.mass") == "lumped" ? MassType::Lumped : MassType::Consistent;
  d.every = static_cast<std::size_t>(c.getInt("diffusion.every"));
  if (c.has("diffusion.dt")) d.dt = c.getFloat("diffusion.dt");
  if (!d.steady) d.initial = c.getFloat("diffusion.initial");
  if (c.has("diffusion.by_property")) d.type_property = c.getString("diffusion.by_property");
  d.diffusivity = detail::readCoefficient(c, "diffusion", "diffusivity");
  d.decay = detail::readCoefficient(c, "diffusion", "decay");
  d.production = detail::readCoefficient(c, "diffusion", "production");
  d.source = detail::readSource(c, "diffusion");
  d.dirichlet = detail::parseRegionValues(c, "diffusion.dirichlet");
  d.flux = detail::parseRegionValues(c, "diffusion.flux");
  d.robin = detail::parseRegionValues(c, "diffusion.robin");
  for (const RegionValue& r : d.robin)
    if (r.value < 0)
      throw c.errorAt("diffusion.robin", std::string("transfer coefficient of '") + boundaryRegionName(r.region) +
                                             "' must be >= 0, got " + formatValue(r.value));
  d.robin_exterior = c.getFloat("diffusion.exterior");
  if (d.steady && d.dirichlet.empty() && d.robin.empty() && d.decay.uniform == 0.0 && d.decay.by_type.empty())
    throw c.errorAt("diffusion.mode",
                    "a steady state needs a Dirichlet or Robin boundary condition or a decay; with zero-flux "
                    "boundaries and no decay it is defined only up to a constant");
  return d;
}

}  // namespace tessella::sim
