#include "tessella/sim/sections/growth_section.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>

#include "tessella/growth/bump_field.hpp"
#include "tessella/growth/division_rule_factory.hpp"
#include "tessella/growth/expression_field.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/growth/meristem_field.hpp"
#include "tessella/growth/radial_field.hpp"
#include "tessella/growth/surface_projection.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::sim {

namespace {

const std::vector<std::string> kFields = {"none", "uniform", "anisotropic", "radial",
                                          "bump", "meristem", "expression"};

std::vector<std::string> ruleChoices() {
  std::vector<std::string> c = {"none"};
  for (const auto& n : growth::divisionRuleNames()) c.push_back(n);
  return c;
}

std::vector<std::string> actualRules() { return growth::divisionRuleNames(); }

// "r=0.1, k=2" -> {r: 0.1, k: 2}; errors name the item.
std::map<std::string, double> parseParameters(const Config& c, const std::string& key) {
  std::map<std::string, double> out;
  std::stringstream all(c.getString(key));
  std::string item;
  while (std::getline(all, item, ',')) {
    const auto trim = [](std::string s) {
      const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
      return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
    };
    item = trim(item);
    if (item.empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw c.errorAt(key, "expected name=value items separated by commas, got '" + item + "'");
    const std::string name = trim(item.substr(0, eq)), value = trim(item.substr(eq + 1));
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (name.empty() || used == 0 || used != value.size())
      throw c.errorAt(key, "parameter '" + item + "' is not name=number");
    if (out.count(name)) throw c.errorAt(key, "parameter '" + name + "' is given twice");
    out[name] = v;
  }
  return out;
}

// Builds a field; growth/ InputErrors become ConfigErrors at `key`.
template <typename Make>
std::shared_ptr<const growth::VelocityField> build(const Config& c, const std::string& key, Make make) {
  try {
    return make();
  } catch (const InputError& e) {
    throw c.errorAt(key, e.what());
  }
}

std::shared_ptr<const growth::VelocityField> readExpression(const Config& c) {
  growth::ExpressionFieldSpec spec;
  if (c.has("growth.expression.parameters"))
    spec.parameters = parseParameters(c, "growth.expression.parameters");
  spec.vx = c.getString("growth.expression.vx");
  spec.vy = c.getString("growth.expression.vy");
  spec.vz = c.getString("growth.expression.vz");
  // Parse each component alone first, so the error points at its own key.
  for (const char* comp : {"vx", "vy", "vz"}) {
    growth::ExpressionFieldSpec one;
    one.parameters = spec.parameters;
    std::string& target = comp[1] == 'x' ? one.vx : comp[1] == 'y' ? one.vy : one.vz;
    target = c.getString(std::string("growth.expression.") + comp);
    build(c, std::string("growth.expression.") + comp,
          [&] { return std::make_shared<growth::ExpressionField>(one); });
  }
  return build(c, "growth.expression.parameters",
               [&] { return std::make_shared<growth::ExpressionField>(spec); });
}

}  // namespace

void declareGrowthSection(Schema& s) {
  s.section("growth",
            "Growth: every step, the vertices move with a velocity field (the PlantGL paper's "
            "kinematic growth). Off unless `field` is set. See docs/growth.md.");
  s.key("growth.field", ValueType::Enum,
        "The velocity field: uniform expansion, anisotropic (per-axis) growth, radial growth, the "
        "paper's bump field (figure 17), a meristem dome with a slow central zone, or expressions.")
      .oneOf(kFields)
      .byDefault(std::string("none"));
  s.key("growth.scheme", ValueType::Enum,
        "Time integration: explicit Euler (first order) or Heun (second order, two field "
        "evaluations per step).")
      .oneOf({"euler", "heun"})
      .byDefault(std::string("heun"));
  s.key("growth.velocities", ValueType::Enum,
        "`field`: every vertex moves with the field. `boundary`: the field is evaluated on the "
        "boundary vertices only and interior velocities are interpolated harmonically "
        "(uniform-weight graph Laplacian), the paper's second mode.")
      .oneOf({"field", "boundary"})
      .byDefault(std::string("field"));
  s.key("growth.surface", ValueType::Enum,
        "Keep a curved-sheet tissue on a surface after every stage: a sphere, a paraboloid, or "
        "the dome the tissue was generated on (tissue.generator: dome). Planar tissues always stay "
        "at z = 0.")
      .oneOf({"none", "sphere", "paraboloid", "dome"})
      .byDefault(std::string("none"));
  s.key("growth.check_inversion", ValueType::Bool,
        "Stop with an error naming the cell and time when a step inverts or collapses a cell "
        "(lower dt); off lets inverted cells through. A non-finite velocity or position is an error "
        "either way.")
      .byDefault(true);

  s.section("growth.uniform", "v = rate (x - center).").activeWhen("growth.field", {"uniform"});
  s.key("growth.uniform.rate", ValueType::Float, "Relative growth rate of lengths (areas grow at 2 rate).")
      .byDefault(0.1);
  s.key("growth.uniform.center", ValueType::Vec3, "Fixed point of the expansion.")
      .byDefault(std::vector<double>{0, 0, 0});

  s.section("growth.anisotropic", "v = diag(rates) (x - center).").activeWhen("growth.field", {"anisotropic"});
  s.key("growth.anisotropic.rates", ValueType::Vec3, "Relative growth rates along x, y and z.")
      .byDefault(std::vector<double>{0.1, 0.0, 0.0});
  s.key("growth.anisotropic.center", ValueType::Vec3, "Fixed point of the growth.")
      .byDefault(std::vector<double>{0, 0, 0});

  s.section("growth.radial", "Points move away from a centre (or an axis) at speed rate * distance^exponent.")
      .activeWhen("growth.field", {"radial"});
  s.key("growth.radial.center", ValueType::Vec3, "Centre of the growth.").byDefault(std::vector<double>{0, 0, 0});
  s.key("growth.radial.axis", ValueType::Vec3,
        "Zero: spherical growth from the centre; otherwise growth away from this axis through the centre.")
      .byDefault(std::vector<double>{0, 0, 0});
  s.key("growth.radial.rate", ValueType::Float, "Speed factor.").byDefault(0.1);
  s.key("growth.radial.exponent", ValueType::Float,
        "1: uniform expansion; 0: constant outward speed; > 1: growth concentrated at the rim.")
      .byDefault(1.0)
      .atLeast(0);

  s.section("growth.bump",
            "The paper's bump field: v = (0, a [1 + b t dx^2/(h + b t)^2] exp(-dx^2/(h + b t)), 0), "
            "dx = x - x0.")
      .activeWhen("growth.field", {"bump"});
  s.key("growth.bump.a", ValueType::Float, "Speed at the bump's centre.").byDefault(1.0);
  s.key("growth.bump.b", ValueType::Float, "Widening rate of the bump.").byDefault(1.0).atLeast(0);
  s.key("growth.bump.h", ValueType::Float, "Squared width of the bump at t = 0.").byDefault(1.0).above(0);
  s.key("growth.bump.x0", ValueType::Float, "Abscissa of the bump's centre.").byDefault(0.0);

  s.section("growth.meristem",
            "Shoot apical meristem: v = k(rho) (x - apex), k rising smoothly (tanh) from central_rate "
            "inside the central zone to peripheral_rate outside; rho is the distance from the axis.")
      .activeWhen("growth.field", {"meristem"});
  s.key("growth.meristem.apex", ValueType::Vec3, "Summit of the dome.").byDefault(std::vector<double>{0, 0, 0});
  s.key("growth.meristem.axis", ValueType::Vec3, "Axis of the dome.").byDefault(std::vector<double>{0, 0, 1});
  s.key("growth.meristem.central_radius", ValueType::Float, "Radius of the slow central zone.")
      .byDefault(1.0)
      .above(0);
  s.key("growth.meristem.transition_width", ValueType::Float, "Width of the transition between the zones.")
      .byDefault(0.2)
      .above(0);
  s.key("growth.meristem.central_rate", ValueType::Float, "Relative growth rate in the central zone.")
      .byDefault(0.02);
  s.key("growth.meristem.peripheral_rate", ValueType::Float, "Relative growth rate in the peripheral zone.")
      .byDefault(0.1);

  s.section("growth.expression",
            "Velocity components as muparser expressions of x, y, z, t and the named parameters.")
      .activeWhen("growth.field", {"expression"});
  s.key("growth.expression.vx", ValueType::String, "x component.").byDefault(std::string("0"));
  s.key("growth.expression.vy", ValueType::String, "y component.").byDefault(std::string("0"));
  s.key("growth.expression.vz", ValueType::String, "z component.").byDefault(std::string("0"));
  s.key("growth.expression.parameters", ValueType::String,
        "Named constants for the expressions, as \"name=value, name=value\".")
      .whenAbsent("no parameters");

  s.section("growth.sphere", "Projection onto the sphere |x - center| = radius.")
      .activeWhen("growth.surface", {"sphere"});
  s.key("growth.sphere.center", ValueType::Vec3, "Centre of the sphere.").byDefault(std::vector<double>{0, 0, 0});
  s.key("growth.sphere.radius", ValueType::Float, "Radius of the sphere.").byDefault(1.0).above(0);

  s.section("growth.paraboloid", "Projection onto the paraboloid z = apex.z - curvature * rho^2.")
      .activeWhen("growth.surface", {"paraboloid"});
  s.key("growth.paraboloid.apex", ValueType::Vec3, "Summit.").byDefault(std::vector<double>{0, 0, 0});
  s.key("growth.paraboloid.curvature", ValueType::Float, "Curvature factor.").byDefault(1.0).above(0);
}

void declareDivisionSection(Schema& s) {
  s.section("division",
            "Division: every step, cells whose size (area in 2D, volume in 3D) exceeds their "
            "threshold divide by the plane the rule chooses. Off unless `rule` is set. See "
            "docs/growth.md.");
  s.key("division.rule", ValueType::Enum,
        "Where cells divide: across the main axis; the shortest wall (Errera); perpendicular to "
        "the mother wall (Hofmeister/Sachs); a random or a fixed direction; the stochastic "
        "shortest wall of Besson and Dumais.")
      .oneOf(ruleChoices())
      .byDefault(std::string("none"));
  s.key("division.threshold", ValueType::Enum,
        "The size threshold: one `size` for all cells; a cell `property`; or `noisy`, drawn per "
        "cell at birth from N(mean, stddev).")
      .oneOf({"fixed", "property", "noisy"})
      .byDefault(std::string("fixed"))
      .activeWhen("division.rule", actualRules());
  s.key("division.size", ValueType::Float, "Size above which a cell divides.")
      .byDefault(1.0)
      .above(0)
      .activeWhen("division.threshold", {"fixed"});
  s.key("division.property", ValueType::String, "Cell property (a float) holding each cell's threshold.")
      .byDefault(std::string("division_threshold"))
      .activeWhen("division.threshold", {"property"});
  s.key("division.mean", ValueType::Float, "Mean of the noisy threshold.")
      .byDefault(1.0)
      .above(0)
      .activeWhen("division.threshold", {"noisy"});
  s.key("division.stddev", ValueType::Float, "Standard deviation of the noisy threshold.")
      .byDefault(0.1)
      .atLeast(0)
      .activeWhen("division.threshold", {"noisy"});
  s.key("division.fixed_normal", ValueType::Vec3, "Normal of every division plane (rule: fixed).")
      .byDefault(std::vector<double>{1, 0, 0})
      .activeWhen("division.rule", {"fixed"});
  s.key("division.beta", ValueType::Float,
        "Besson-Dumais selectivity: candidate walls are chosen with probability ~ exp(-beta L / L_min).")
      .byDefault(10.0)
      .atLeast(0)
      .activeWhen("division.rule", {"besson_dumais"});
  s.key("division.junction_tolerance", ValueType::Float,
        "Hofmeister/Sachs: how far (relative to the cell size) the new wall keeps from existing "
        "junctions on the mother wall, avoiding four-way junctions.")
      .byDefault(0.05)
      .atLeast(0)
      .atMost(0.45)
      .activeWhen("division.rule", {"perpendicular_to_mother_wall"});
  s.key("division.max_attempts", ValueType::Int,
        "Planes tried per cell when a cut is degenerate (the rule's, then slightly rotated and "
        "shifted ones); after that the cell waits for the next step.")
      .byDefault(std::int64_t{5})
      .atLeast(1)
      .atMost(100)
      .activeWhen("division.rule", actualRules());
  s.section("division.gate",
            "Division gated by a field: a cell over its size threshold divides only if the cell "
            "average of `field` (a diffusion species or compartment field, or another cell property "
            "the solver sections write) exceeds `above`. Before the field's first solve no cell divides.")
      .activeWhen("division.rule", actualRules());
  s.key("division.gate.field", ValueType::String, "The gating field (e.g. the diffusion species' name).")
      .whenAbsent("no gate");
  s.key("division.gate.above", ValueType::Float, "Cells divide only where the field is above this value.")
      .byDefault(0.0);
}

GrowthSpec readGrowthSection(const Config& c, const TissueSpec& tissue) {
  GrowthSpec g;
  const std::string field = c.getString("growth.field");
  g.options.scheme = growth::parseScheme(c.getString("growth.scheme"));
  g.options.source = c.getString("growth.velocities") == "boundary" ? growth::VelocitySource::HarmonicFromControl
                                                                    : growth::VelocitySource::Field;
  g.options.check_inversion = c.getBool("growth.check_inversion");
  const std::string surface = c.getString("growth.surface");
  if (surface == "sphere") {
    g.options.projection = growth::sphereProjection(c.getVec("growth.sphere.center"), c.getFloat("growth.sphere.radius"));
  } else if (surface == "paraboloid") {
    g.options.projection =
        growth::paraboloidProjection(c.getVec("growth.paraboloid.apex"), c.getFloat("growth.paraboloid.curvature"));
  } else if (surface == "dome") {
    const std::optional<Dome> dome = tissueDome(tissue);
    if (!dome)
      throw c.errorAt("growth.surface",
                      "'dome' needs tissue.generator: dome, or a snapshot of a run on a dome (which records it)");
    g.options.projection = growth::domeProjection(*dome);
  }
  if (field == "none") return g;
  if (field == "uniform") {
    g.field = build(c, "growth.uniform.rate", [&] {
      return std::make_shared<growth::LinearField>(
          growth::uniformExpansion(c.getFloat("growth.uniform.rate"), c.getVec("growth.uniform.center")));
    });
  } else if (field == "anisotropic") {
    g.field = build(c, "growth.anisotropic.rates", [&] {
      return std::make_shared<growth::LinearField>(growth::anisotropicGrowth(
          c.getVec("growth.anisotropic.rates"), c.getVec("growth.anisotropic.center")));
    });
  } else if (field == "radial") {
    g.field = build(c, "growth.radial.rate", [&] {
      return std::make_shared<growth::RadialField>(growth::RadialFieldParams{
          .center = c.getVec("growth.radial.center"), .axis = c.getVec("growth.radial.axis"),
          .rate = c.getFloat("growth.radial.rate"), .exponent = c.getFloat("growth.radial.exponent")});
    });
  } else if (field == "bump") {
    g.field = build(c, "growth.bump.h", [&] {
      return std::make_shared<growth::BumpField>(growth::BumpFieldParams{
          .a = c.getFloat("growth.bump.a"), .b = c.getFloat("growth.bump.b"),
          .h = c.getFloat("growth.bump.h"), .x0 = c.getFloat("growth.bump.x0")});
    });
  } else if (field == "meristem") {
    g.field = build(c, "growth.meristem.axis", [&] {
      return std::make_shared<growth::MeristemField>(growth::MeristemFieldParams{
          .apex = c.getVec("growth.meristem.apex"), .axis = c.getVec("growth.meristem.axis"),
          .central_radius = c.getFloat("growth.meristem.central_radius"),
          .transition_width = c.getFloat("growth.meristem.transition_width"),
          .central_rate = c.getFloat("growth.meristem.central_rate"),
          .peripheral_rate = c.getFloat("growth.meristem.peripheral_rate")});
    });
  } else if (field == "expression") {
    g.field = readExpression(c);
  }
  return g;
}

DivisionSpec readDivisionSection(const Config& c) {
  DivisionSpec d;
  const std::string rule = c.getString("division.rule");
  if (rule == "none") return d;
  growth::DivisionRuleParams params;
  if (rule == "fixed") {
    params.fixed_normal = c.getVec("division.fixed_normal");
    if (!(params.fixed_normal.norm() > 0)) throw c.errorAt("division.fixed_normal", "must be a non-zero vector");
  }
  if (rule == "besson_dumais") params.beta = c.getFloat("division.beta");
  if (rule == "perpendicular_to_mother_wall") params.junction_tolerance = c.getFloat("division.junction_tolerance");
  try {
    d.rule = growth::makeDivisionRule(rule, params);
  } catch (const InputError& e) {
    throw c.errorAt("division.rule", e.what());
  }
  const std::string threshold = c.getString("division.threshold");
  if (threshold == "fixed") d.threshold = growth::SizeThreshold::fixed(c.getFloat("division.size"));
  if (threshold == "property") d.threshold = growth::SizeThreshold::fromProperty(c.getString("division.property"));
  if (threshold == "noisy")
    d.threshold = growth::SizeThreshold::noisy(c.getFloat("division.mean"), c.getFloat("division.stddev"));
  d.options.max_attempts = static_cast<int>(c.getInt("division.max_attempts"));
  if (c.has("division.gate.field")) {
    d.gate_field = c.getString("division.gate.field");
    d.gate_above = c.getFloat("division.gate.above");
  }
  return d;
}

void checkDivisionGate(const Config& c, const DivisionSpec& d, const std::vector<std::string>& fields) {
  if (d.gate_field.empty() || !d.rule) return;
  if (std::find(fields.begin(), fields.end(), d.gate_field) != fields.end()) return;
  std::string known;
  for (const auto& f : fields) known += (known.empty() ? "" : ", ") + f;
  throw c.errorAt("division.gate.field", "'" + d.gate_field + "' is not a field of the solver sections" +
                                             (known.empty() ? std::string(" (none is on)") : " (known: " + known + ")"));
}

}  // namespace tessella::sim
