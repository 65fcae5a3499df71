// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/mechanics_section.hpp"

#include "../config/exact_text.hpp"

#include "tessella/mechanics/equilibrium.hpp"
#include "tessella/mechanics/errors.hpp"
#include "tessella/mechanics/planar_dofs.hpp"
#include "tessella/mechanics/wall_state.hpp"
#include "tessella/mechanics/wall_stress.hpp"
#include "tessella/sim/config/registry_config.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace tessella::sim {
namespace {

const std::vector<std::string>& sideNames() {
  static const std::vector<std::string> names = {"x_min", "x_max", "y_min", "y_max"};
  return names;
}

// The face columns the membranes of a 3D tissue read besides their rest state: a snapshot holds cells only, and
// a 3D tissue's faces are its walls, so these go to the run state as "mechanics.wall.<name>".
constexpr const char* kSavedWallColumns[] = {mechanics::kFibreRatioName, mechanics::kMembraneRestRatioName};

// "<policy> <default> <value per live wall in slot order>", every number as exact text.
std::string wallColumnText(const Tissue& tissue, const char* name) {
  const auto& column = tissue.wallProperties().get<double>(name);
  std::string text = std::string(divisionPolicyName(column.policy())) + " " + formatNumber(column.defaultValue());
  for (WallId w : tissue.walls()) text += " " + formatNumber(column[w]);
  return text;
}

// Reads wallColumnText's output back into the wall column `name` (added when missing).
void restoreWallColumn(Tissue& tissue, const char* name, const std::string& text, const std::string& snapshot) {
  const std::string key = std::string("mechanics.wall.") + name;
  std::istringstream in(text);
  std::string word;
  in >> word;
  std::optional<DivisionPolicy> policy;
  for (DivisionPolicy p : {DivisionPolicy::Copy, DivisionPolicy::SplitByMeasure, DivisionPolicy::Reset})
    if (word == divisionPolicyName(p)) policy = p;
  if (!policy)
    throw InputError("snapshot '" + snapshot + "': its run state " + key + " has the division policy '" + word +
                     "'; a restart restores copy, split_by_measure or reset");
  std::vector<double> values;
  while (in >> word) {
    double v = 0.0;
    if (!detail::parseExact(word, v))
      throw InputError("snapshot '" + snapshot + "': its run state " + key + " holds '" + word + "', not a number");
    values.push_back(v);
  }
  if (values.size() != tissue.numWalls() + 1)
    throw InputError("snapshot '" + snapshot + "': its run state " + key + " has " +
                     std::to_string(values.empty() ? 0 : values.size() - 1) + " values (after its default) for " +
                     std::to_string(tissue.numWalls()) + " walls");
  PropertyStore& walls = tissue.wallProperties();
  if (walls.has(name)) walls.remove(name);
  auto& column = walls.add<double>(name, values[0], *policy);
  std::size_t i = 1;
  for (WallId w : tissue.walls()) column[w] = values[i++];
}

}  // namespace

MechanicsStage::MechanicsStage(MechanicsSpec spec) : spec_(std::move(spec)) { spec_.params.check(); }

std::vector<std::string> MechanicsStage::cellPropertiesWritten() const {
  if (spec_.membranes)
    return {mechanics::kTurgorPressureName, mechanics::kExtensibilityName, mechanics::kYoungScaleName,
            mechanics::kStressMaxName,      mechanics::kStressMinName,      mechanics::kStrainMaxName,
            mechanics::kStrainMinName,      mechanics::kGrowthRateName};
  return {mechanics::kTurgorPressureName, mechanics::kExtensibilityName, kMeanStrainName, kMeanTensionName,
          mechanics::kStressMaxName, mechanics::kStressMinName};
}

void MechanicsStage::prepare(Tissue& tissue, double /*time*/) {
  if (spec_.membranes) {
    if (tissue.dim() == 2 && tissue.embedding() != Embedding::Surface)
      throw InputError("mechanics.model: membranes need a curved sheet (embedding surface) or a 3D tissue; "
                       "this tissue is planar (use wall_springs)");
    if (spec_.membrane.support == mechanics::MembraneGrowthParams::Support::Boundary && tissue.dim() != 2)
      throw InputError("mechanics.membrane_support: boundary holds a sheet's rims; this tissue is 3D (use base)");
    mechanics::cellOutput(tissue, mechanics::kTurgorPressureName, spec_.membrane.pressure);
    // phi per cell (a model may change it between steps; a restart keeps the snapshot's values).
    mechanics::cellOutput(tissue, mechanics::kExtensibilityName, spec_.membrane.growth.extensibility);
    mechanics::cellOutput(tissue, mechanics::kYoungScaleName, 1.0);
    // Zero before the first equilibrium (a restart keeps the snapshot's values).
    for (const char* name : {mechanics::kStressMaxName, mechanics::kStressMinName, mechanics::kStrainMaxName,
                             mechanics::kStrainMinName, mechanics::kGrowthRateName})
      mechanics::cellOutput(tissue, name);
    PropertyStore& cells = tissue.cellProperties();
    if (!cells.has(mechanics::kWallStressName))
      cells.add<Sym3>(mechanics::kWallStressName, Sym3{}, DivisionPolicy::Copy);
    if (!cells.has(mechanics::kStressDirectionName))
      cells.add<Vec3>(mechanics::kStressDirectionName, Vec3::Zero(), DivisionPolicy::Copy);
    mechanics::prepareMembranePolygonOutputs(tissue);  // zero until the first equilibrium
    if (!spec_.soft_center) {
      Vec3 sum = Vec3::Zero();
      for (VertexId v : tissue.vertices()) sum += tissue.position(v);
      spec_.soft_center = sum / static_cast<double>(std::max<std::size_t>(tissue.numVertices(), 1));
    }
    if (spec_.membrane.support == mechanics::MembraneGrowthParams::Support::Point && !spec_.membrane.point) {
      // The anchor is the vertex nearest the start's vertex mean (a restart reads the point back below).
      Vec3 sum = Vec3::Zero();
      for (VertexId v : tissue.vertices()) sum += tissue.position(v);
      spec_.membrane.point = sum / static_cast<double>(std::max<std::size_t>(tissue.numVertices(), 1));
    }
    if (spec_.membrane.support == mechanics::MembraneGrowthParams::Support::Base && !spec_.membrane.base_height) {
      // The base plane is where the run starts (a restart reads it back below).
      double zmin = std::numeric_limits<double>::infinity();
      for (VertexId v : tissue.vertices()) zmin = std::min(zmin, tissue.position(v).z());
      if (std::isfinite(zmin)) spec_.membrane.base_height = zmin;
    }
    if (restart_) {
      const auto& [snapshot, state] = *restart_;
      if (state.count("mechanics.base_height") &&
          spec_.membrane.support == mechanics::MembraneGrowthParams::Support::Base) {
        double z = 0.0;
        if (!detail::parseExact(state.at("mechanics.base_height"), z))
          throw InputError("snapshot '" + snapshot + "': mechanics.base_height holds '" +
                           state.at("mechanics.base_height") + "', not a number");
        spec_.membrane.base_height = z;
      }
      if (state.count("mechanics.support_point") &&
          spec_.membrane.support == mechanics::MembraneGrowthParams::Support::Point) {
        std::istringstream in(state.at("mechanics.support_point"));
        Vec3 q;
        for (int k = 0; k < 3; ++k) {
          std::string word;
          in >> word;
          if (!detail::parseExact(word, q[k]))
            throw InputError("snapshot '" + snapshot + "': mechanics.support_point holds '" + word + "'");
        }
        spec_.membrane.point = q;
      }
      if (state.count("mechanics.membrane_rest"))
        membrane_state_.fromText(tissue, state.at("mechanics.membrane_rest"), "snapshot '" + snapshot + "'");
      if (tissue.dim() == 3)
        for (const char* name : kSavedWallColumns)
          if (state.count(std::string("mechanics.wall.") + name))
            restoreWallColumn(tissue, name, state.at(std::string("mechanics.wall.") + name), snapshot);
      if (state.count("mechanics.soft_center")) {
        std::istringstream in(state.at("mechanics.soft_center"));
        Vec3 c;
        for (int k = 0; k < 3; ++k) {
          std::string word;
          in >> word;
          if (!detail::parseExact(word, c[k]))
            throw InputError("snapshot '" + snapshot + "': mechanics.soft_center holds '" + word + "'");
        }
        spec_.soft_center = c;
      }
    }
    return;
  }
  mechanics::requirePlanar(tissue, "the mechanics section");
  mechanics::prepareTurgorState(tissue, spec_.params);
  mechanics::cellOutput(tissue, mechanics::kExtensibilityName, spec_.params.growth.extensibility);
  if (restart_) restore(tissue);
  mechanics::initialiseRestLengths(tissue);  // the starting shape is at rest (walls not restored)
  mechanics::cellOutput(tissue, kMeanStrainName);
  mechanics::cellOutput(tissue, kMeanTensionName);
  // Zero before the first equilibrium (a restart keeps the snapshot's values).
  if (!tissue.cellProperties().has(mechanics::kWallStressName)) mechanics::writeCellWallStress(tissue);
  if (spec_.support == MechanicsSupport::Point && !spec_.pin_point) {
    Vec3 sum = Vec3::Zero();
    for (VertexId v : tissue.vertices()) sum += tissue.position(v);
    spec_.pin_point = sum / static_cast<double>(std::max<std::size_t>(tissue.numVertices(), 1));
  }
}

io::WallArrays MechanicsStage::wallArrays(const Tissue& tissue) const {
  if (spec_.membranes) {
    if (tissue.dim() != 3) return {};
    return io::wallPropertyArrays(tissue, mechanics::membraneWallOutputNames());
  }
  io::WallArrays a = io::wallPropertyArrays(tissue, {mechanics::kRestLengthName, mechanics::kWallStrainName,
                                                     mechanics::kWallTensionName, mechanics::kGrowthRateName});
  auto& direction = a.vectors["wall_direction"];
  for (WallId w : tissue.walls()) {
    const auto uv = tissue.topology().edgeVertices(EdgeId(w.index()));
    const Vec3 d = tissue.position(uv[1]) - tissue.position(uv[0]);
    direction.push_back(d.norm() > 0.0 ? Vec3(d.normalized()) : Vec3::Zero());
  }
  return a;
}

std::vector<std::string> MechanicsStage::sheetCellOutputNames() {
  std::vector<std::string> names = mechanics::membraneWallOutputNames();
  names.push_back(mechanics::kTurgorPressureName);
  return names;
}

io::WallArrays MechanicsStage::meshCellArrays(const Tissue& tissue) const {
  if (!spec_.membranes || tissue.dim() != 2 || tissue.embedding() != Embedding::Surface) return {};
  return io::cellPropertyArrays(tissue, sheetCellOutputNames());
}

void MechanicsStage::saveState(const Tissue& tissue, const std::string& snapshot_path,
                               const io::VtuOptions& options, io::RunState& state) const {
  if (tissue.numWalls() > 0 && (!spec_.membranes || tissue.dim() == 3))
    io::writeWallsVtu(tissue, io::besideSnapshotPath(snapshot_path, "walls"), wallArrays(tissue), options);
  if (spec_.membranes) {
    state["mechanics.membrane_rest"] = membrane_state_.toText(tissue);
    if (tissue.dim() == 3)
      for (const char* name : kSavedWallColumns)
        if (tissue.wallProperties().has(name))
          state[std::string("mechanics.wall.") + name] = wallColumnText(tissue, name);
    if (spec_.membrane.base_height) state["mechanics.base_height"] = formatNumber(*spec_.membrane.base_height);
    if (spec_.membrane.point)
      state["mechanics.support_point"] = formatNumber(spec_.membrane.point->x()) + " " +
                                         formatNumber(spec_.membrane.point->y()) + " " +
                                         formatNumber(spec_.membrane.point->z());
    if (spec_.soft_center)
      state["mechanics.soft_center"] = formatNumber(spec_.soft_center->x()) + " " +
                                       formatNumber(spec_.soft_center->y()) + " " +
                                       formatNumber(spec_.soft_center->z());
    return;
  }
  std::string text;
  if (tissue.wallProperties().has(mechanics::kRestLengthName)) {
    const auto& rest = tissue.wallProperties().get<double>(mechanics::kRestLengthName);
    for (WallId w : tissue.walls()) text += (text.empty() ? "" : " ") + formatNumber(rest[w]);
  }
  state["mechanics.rest_length"] = text;
  if (spec_.pin_point)
    state["mechanics.pin_point"] = formatNumber(spec_.pin_point->x()) + " " + formatNumber(spec_.pin_point->y()) +
                                   " " + formatNumber(spec_.pin_point->z());
}

void MechanicsStage::continueFrom(const std::string& snapshot_path, const io::RunState& state) {
  restart_ = std::make_pair(snapshot_path, state);
}

void MechanicsStage::restore(Tissue& tissue) {
  const auto& [snapshot, state] = *restart_;
  auto numbers = [&](const std::string& key) {
    std::vector<double> values;
    std::istringstream in(state.at(key));
    std::string word;
    while (in >> word) {
      double v = 0.0;
      if (!detail::parseExact(word, v))
        throw InputError("snapshot '" + snapshot + "': its run state " + key + " holds '" + word +
                         "', not a number");
      values.push_back(v);
    }
    return values;
  };
  if (state.count("mechanics.pin_point") && spec_.support == MechanicsSupport::Point) {
    const std::vector<double> p = numbers("mechanics.pin_point");
    if (p.size() != 3) throw InputError("snapshot '" + snapshot + "': mechanics.pin_point is not three numbers");
    spec_.pin_point = Vec3(p[0], p[1], p[2]);
  }
  if (!state.count("mechanics.rest_length")) return;  // walls start at rest
  const std::vector<double> values = numbers("mechanics.rest_length");
  if (values.size() != tissue.numWalls())
    throw InputError("snapshot '" + snapshot + "': its run state has " + std::to_string(values.size()) +
                     " rest lengths (mechanics.rest_length) for " + std::to_string(tissue.numWalls()) + " walls");
  auto& rest = mechanics::restLengths(tissue);
  std::size_t i = 0;
  for (WallId w : tissue.walls()) rest[w] = values[i++];
}

void MechanicsStage::applyMembranes(Tissue& tissue, const StepContext& context) {
  mechanics::MembraneGrowthParams params = spec_.membrane;
  params.solver.context = "mechanics, step " + std::to_string(context.clock_step + 1) + ", time " +
                          formatNumber(context.time);
  if (spec_.soft_radius > 0.0) {
    auto& young = mechanics::cellOutput(tissue, mechanics::kYoungScaleName, 1.0);
    for (CellId c : tissue.cells()) {
      const Vec3 d = cellCentroid(tissue, c) - *spec_.soft_center;
      const double s = std::min(std::hypot(d.x(), d.y()) / spec_.soft_radius, 1.0);
      young[c] = spec_.soft_factor + (1.0 - spec_.soft_factor) * s * s;
    }
  }
  membrane_report_ = mechanics::membraneGrowthStep(tissue, params, membrane_state_, context.dt, context.rng);
}

void MechanicsStage::apply(Tissue& tissue, const StepContext& context) {
  if (spec_.membranes) {
    applyMembranes(tissue, context);
    return;
  }
  mechanics::TurgorGrowthParams params = spec_.params;
  params.solver.context = "mechanics, step " + std::to_string(context.clock_step + 1) + ", time " +
                          formatNumber(context.time);
  if (spec_.support == MechanicsSupport::Point) {
    params.supports.pin = true;
    params.supports.pin_point = *spec_.pin_point;
  } else {
    // The side of the current bounding box, within 1e-6 of its diagonal.
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (VertexId v : tissue.vertices()) {
      lo = lo.cwiseMin(tissue.position(v));
      hi = hi.cwiseMax(tissue.position(v));
    }
    const double tol = 1e-6 * (hi - lo).norm();
    const int axis = spec_.fixed_side / 2;
    const double bound = spec_.fixed_side % 2 == 0 ? lo[axis] : hi[axis];
    params.supports.box = true;
    params.supports.box_lo = lo - Vec3::Constant(1.0);
    params.supports.box_hi = hi + Vec3::Constant(1.0);
    params.supports.box_lo[axis] = bound - tol;
    params.supports.box_hi[axis] = bound + tol;
  }
  report_ = mechanics::turgorGrowthStep(tissue, params, context.dt);
  writeCellMeans(tissue);
  mechanics::writeCellWallStress(tissue);
}

void MechanicsStage::writeCellMeans(Tissue& tissue) const {
  const auto& strain = tissue.wallProperties().get<double>(mechanics::kWallStrainName);
  const auto& tension = tissue.wallProperties().get<double>(mechanics::kWallTensionName);
  auto& mean_strain = mechanics::cellOutput(tissue, kMeanStrainName);
  auto& mean_tension = mechanics::cellOutput(tissue, kMeanTensionName);
  for (CellId c : tissue.cells()) {
    double length = 0.0, s = 0.0, t = 0.0;
    for (WallId w : tissue.cellWalls(c)) {
      const double l = wallMeasure(tissue, w);
      length += l;
      s += l * strain[w];
      t += l * tension[w];
    }
    mean_strain[c] = length > 0.0 ? s / length : 0.0;
    mean_tension[c] = length > 0.0 ? t / length : 0.0;
  }
}

void declareMechanicsSection(Schema& s) {
  s.section("mechanics",
            "Turgor-driven growth. `wall_springs` (planar 2D tissues): walls are linear elastic springs "
            "(tension E t (L - L0) / L0), cells push with their turgor pressure, the quasi-static equilibrium is "
            "solved by Newton every step and the tissue moves there; rest lengths then grow where the wall strain "
            "exceeds `threshold` (Lockhart-Ortega). Writes turgor_pressure, mean_wall_strain, "
            "mean_wall_tension and the walls' stress (wall_stress, stress_max, stress_min, stress_direction) "
            "per cell (and rest_length, wall_strain, wall_tension, growth_rate per wall, written beside every "
            "snapshot as <stem>.walls.vtu, listed in <series>.walls.pvd). `membranes` (curved sheets, 3D "
            "tissues): every sheet cell or 3D wall is a fan of membrane triangles whose rest shapes grow along "
            "their principal stretches; writes turgor_pressure, young_scale, the mean membrane tension (wall_stress, "
            "stress_max, stress_min, stress_direction), strain_max, strain_min and growth_rate per cell, and "
            "on a 3D tissue's walls their own tension and strain (tensors, principal values and directions), fibre "
            "direction, rest area, growth rate and pressure load (<stem>.walls.vtu). Off unless "
            "`model` is set. See docs/mechanics.md.");
  s.key("mechanics.model", ValueType::Enum,
        "The mechanical model. `wall_springs`: walls as springs, cells under turgor (planar 2D tissues). "
        "`membranes`: every cell of a curved sheet, every wall of a 3D tissue a membrane (the fan of "
        "membrane triangles (`material`) from its vertex mean; a polygon whose fan folds: from its kernel centroid, "
        "or its ear-clipped triangles), cells under turgor, the base or the rim fixed.")
      .oneOf({"none", "wall_springs", "membranes"})
      .byDefault(std::string("none"));
  const std::vector<std::string> on = {"wall_springs", "membranes"};
  const std::vector<std::string> springs = {"wall_springs"};
  const std::vector<std::string> membranes = {"membranes"};
  s.key("mechanics.pressure", ValueType::Float,
        "Turgor pressure P of every cell (the cell property turgor_pressure; a model may change it per cell).")
      .byDefault(0.1)
      .atLeast(0)
      .activeWhen("mechanics.model", on);
  s.key("mechanics.young", ValueType::Float, "Young's modulus E of the walls.")
      .byDefault(1.0)
      .above(0)
      .activeWhen("mechanics.model", on);
  s.key("mechanics.thickness", ValueType::Float, "Wall thickness t: a wall's stiffness is E t.")
      .byDefault(1.0)
      .above(0)
      .activeWhen("mechanics.model", on);
  s.key("mechanics.extensibility", ValueType::Float,
        "Wall extensibility phi: dL0/dt = phi L0 max(strain - threshold, 0). 0: no growth. The default of the "
        "cell property extensibility, which a model may set per cell between steps (a wall grows with the mean of "
        "its cells').")
      .byDefault(0.0)
      .atLeast(0)
      .activeWhen("mechanics.model", on);
  s.key("mechanics.threshold", ValueType::Float, "Yield strain below which walls do not grow.")
      .byDefault(0.0)
      .atLeast(0)
      .activeWhen("mechanics.model", on);
  s.key("mechanics.support", ValueType::Enum,
        "What holds the tissue against rigid motions. `point`: the vertex nearest `pin_point` is fixed and "
        "the rotation about it removed; `region`: the vertices on one side of the bounding box are fixed.")
      .oneOf({"point", "region"})
      .byDefault(std::string("point"))
      .activeWhen("mechanics.model", springs);
  s.key("mechanics.pin_point", ValueType::Vec3, "The pinned point.")
      .whenAbsent("the mean of the vertex positions when the run starts")
      .activeWhen("mechanics.support", {"point"});
  s.key("mechanics.fixed_region", ValueType::Enum,
        "The side of the bounding box (as it is at each step) whose vertices are fixed.")
      .oneOf(sideNames())
      .byDefault(std::string("x_min"))
      .activeWhen("mechanics.support", {"region"});
  std::string laws = "The membranes' material law (docs/mechanics.md, \"Membrane materials\").";
  for (const auto& law : mechanics::membraneLaws().entries()) laws += " `" + law.name + "`: " + law.doc;
  s.key("mechanics.material", ValueType::Enum, laws)
      .oneOf(mechanics::membraneLaws().names())
      .byDefault(std::string("st_venant_kirchhoff"))
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.poisson", ValueType::Float, "Poisson's ratio nu of the membranes (nu^2 < fibre_ratio).")
      .byDefault(0.3)
      .above(-1)
      .atMost(0.5)
      .activeWhen("mechanics.material", {"st_venant_kirchhoff", "compressible_neo_hookean"});
  s.key("mechanics.fibre_ratio", ValueType::Float,
        "Stiffness along the fibres over the stiffness across them (1: isotropic; the neo-Hookean laws: >= 1). "
        "A polygon whose face has the property fibre_ratio (a sheet's cell, a 3D tissue's wall) uses its value "
        "instead.")
      .byDefault(1.0)
      .above(0)
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.fibres", ValueType::Enum,
        "The fibre direction of each membrane polygon, projected on each fan triangle. `none`: isotropic frame "
        "(its first edge); `fixed`: `fibre_vector`; `circumferential`: around the axis through `fibre_point` "
        "along `fibre_vector` (axis x (centroid - point)).")
      .oneOf({"none", "fixed", "circumferential"})
      .byDefault(std::string("none"))
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.fibre_vector", ValueType::Vec3, "The fixed fibre direction, or the circumferential axis.")
      .byDefault(std::vector<double>{0, 0, 1})
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.fibre_point", ValueType::Vec3, "A point on the circumferential fibres' axis.")
      .byDefault(std::vector<double>{0, 0, 0})
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.feedback_rate", ValueType::Float,
        "Stress feedback: each polygon's fibre turns toward its maximal principal tension, its angle decaying as "
        "exp(-feedback_rate t) (docs/mechanics.md). 0: off.")
      .byDefault(0.0)
      .atLeast(0)
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.feedback_noise", ValueType::Float,
        "Standard deviation of the fibre angle's random kick per square root of time (radians), drawn from the "
        "run's random stream. 0: none.")
      .byDefault(0.0)
      .atLeast(0)
      .activeWhen("mechanics.model", membranes);
  std::string supports =
      "What holds the membranes against rigid motions (with the `symmetry_planes`, which apply to every support; "
      "a step whose supports leave a rigid motion free fails, naming it).";
  for (const auto& support : mechanics::membraneSupports().entries())
    supports += " `" + support.name + "`: " + support.doc + ".";
  s.key("mechanics.membrane_support", ValueType::Enum,
        supports + " A rim each of whose edges is fixed or lies in a symmetry plane is not loaded.")
      .oneOf(mechanics::membraneSupports().names())
      .byDefault(std::string("base"))
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.symmetry_planes", ValueType::String,
        "Symmetry planes normal to the axes, as `x = c`, `y = c` or `z = c` separated by commas (for example "
        "\"x = 0, y = 0\" for a quarter): a vertex within `plane_distance` of a plane keeps its normal "
        "displacement zero (it slides in the plane). A sheet's rims along them are closed in the planes (the cone "
        "origin lies on each). Empty: none.")
      .byDefault(std::string(""))
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.plane_distance", ValueType::Float,
        "Vertices within this distance of a symmetry plane are held on it.")
      .byDefault(1e-6)
      .atLeast(0)
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.support_point", ValueType::Vec3,
        "The point support's anchor: the vertex nearest this point (each step).")
      .whenAbsent("the mean of the vertex positions when the run starts")
      .activeWhen("mechanics.membrane_support", {"point"});
  s.key("mechanics.base_distance", ValueType::Float,
        "Vertices within this distance above the lowest vertex (z) are fixed: the base ring of a dome or "
        "cylinder, the bottom of a 3D tissue.")
      .byDefault(1e-6)
      .atLeast(0)
      .activeWhen("mechanics.membrane_support", {"base"});
  s.key("mechanics.soft_radius", ValueType::Float,
        "Soft summit: a cell's Young's modulus is young (f + (1 - f) min(r / soft_radius, 1)^2), r the "
        "horizontal distance of its centroid from soft_center, f = soft_factor (the cell property "
        "young_scale). 0: uniform.")
      .byDefault(0.0)
      .atLeast(0)
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.soft_factor", ValueType::Float, "The summit's Young's modulus over `young`.")
      .byDefault(1.0)
      .above(0)
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.soft_center", ValueType::Vec3, "The summit's axis (a vertical line through this point).")
      .whenAbsent("the mean of the vertex positions when the run starts")
      .activeWhen("mechanics.model", membranes);
  s.key("mechanics.tolerance", ValueType::Float,
        "Newton stops when the out-of-balance force is below tolerance times the force scale.")
      .byDefault(1e-10)
      .above(0)
      .activeWhen("mechanics.model", on);
  s.key("mechanics.max_iterations", ValueType::Int, "Newton iterations before the step fails.")
      .byDefault(std::int64_t{50})
      .atLeast(1)
      .atMost(10000)
      .activeWhen("mechanics.model", on);
  s.key("mechanics.linear_solver", ValueType::Enum,
        "The direct solver of Newton's tangent systems: `auto` (CHOLMOD's supernodal Cholesky for tangents of 5000 "
        "free dofs or more when Tessella is built with CHOLMOD, else Eigen's simplicial LDL^T up to 10^5 unknowns), "
        "`ldlt` (Eigen's LDL^T at any size) or `cholmod` (CHOLMOD at any size, several times faster on large "
        "tissues; builds with CHOLMOD only). Results agree within Newton's tolerance.")
      .oneOf(mechanics::tangentSolvers().names())
      .byDefault(std::string("auto"))
      .activeWhen("mechanics.model", on);
}

MechanicsSpec readMechanicsSection(const Config& c) {
  MechanicsSpec m;
  if (c.getString("mechanics.model") == "none") return m;
  m.enabled = true;
  m.params.pressure = c.getFloat("mechanics.pressure");
  m.params.youngs_modulus = c.getFloat("mechanics.young");
  m.params.thickness = c.getFloat("mechanics.thickness");
  m.params.growth.extensibility = c.getFloat("mechanics.extensibility");
  m.params.growth.threshold = c.getFloat("mechanics.threshold");
  m.params.solver.relative_tolerance = c.getFloat("mechanics.tolerance");
  m.params.solver.max_iterations = static_cast<int>(c.getInt("mechanics.max_iterations"));
  m.params.solver.linear.method = parseFromConfig(c, mechanics::tangentSolvers(), "mechanics.linear_solver");
  if (!solvers::solverAvailable(m.params.solver.linear.method))
    throw c.errorAt("mechanics.linear_solver", "'" + c.getString("mechanics.linear_solver") +
                                                   "' is not in this build of Tessella (built without CHOLMOD); "
                                                   "use auto or ldlt");
  if (c.getString("mechanics.model") == "membranes") {
    m.membranes = true;
    mechanics::MembraneGrowthParams& p = m.membrane;
    p.material.young = m.params.youngs_modulus;
    p.material.thickness = m.params.thickness;
    p.material.law = parseFromConfig(c, mechanics::membraneLaws(), "mechanics.material");
    if (p.material.law != mechanics::MembraneLaw::NeoHookean) p.material.poisson = c.getFloat("mechanics.poisson");
    p.material.fibre_ratio = c.getFloat("mechanics.fibre_ratio");
    p.pressure = m.params.pressure;
    p.growth = m.params.growth;
    p.solver = m.params.solver;
    p.support = parseFromConfig(c, mechanics::membraneSupports(), "mechanics.membrane_support");
    if (p.support == mechanics::MembraneGrowthParams::Support::Base)
      p.base_distance = c.getFloat("mechanics.base_distance");
    try {
      p.planes = mechanics::parseSymmetryPlanes(c.getString("mechanics.symmetry_planes"), "symmetry_planes");
    } catch (const InputError& e) {
      throw c.errorAt("mechanics.symmetry_planes", e.what());
    }
    if (p.support == mechanics::MembraneGrowthParams::Support::Symmetry && p.planes.empty())
      throw c.errorAt("mechanics.membrane_support", "'symmetry' holds the tissue by its symmetry planes; "
                                                    "mechanics.symmetry_planes gives none");
    p.plane_distance = c.getFloat("mechanics.plane_distance");
    if (p.support == mechanics::MembraneGrowthParams::Support::Point && c.has("mechanics.support_point"))
      p.point = c.getVec("mechanics.support_point");
    p.feedback.rate = c.getFloat("mechanics.feedback_rate");
    p.feedback.noise = c.getFloat("mechanics.feedback_noise");
    const std::string fibres = c.getString("mechanics.fibres");
    p.fibres.kind = fibres == "fixed"             ? mechanics::FibreRule::Kind::Fixed
                    : fibres == "circumferential" ? mechanics::FibreRule::Kind::Circumferential
                                                  : mechanics::FibreRule::Kind::None;
    p.fibres.vector = c.getVec("mechanics.fibre_vector");
    p.fibres.point = c.getVec("mechanics.fibre_point");
    if (p.fibres.kind != mechanics::FibreRule::Kind::None && !(p.fibres.vector.norm() > 0.0))
      throw c.errorAt("mechanics.fibre_vector", "must not be zero");
    try {
      p.material.check();
    } catch (const InputError& e) {
      // The message names the parameter: "membrane material: <name> <value> ...".
      const bool poisson = std::string(e.what()).find("membrane material: poisson") != std::string::npos;
      throw c.errorAt(poisson ? "mechanics.poisson" : "mechanics.fibre_ratio", e.what());
    }
    m.soft_radius = c.getFloat("mechanics.soft_radius");
    m.soft_factor = c.getFloat("mechanics.soft_factor");
    if (c.has("mechanics.soft_center")) m.soft_center = c.getVec("mechanics.soft_center");
    return m;
  }
  if (c.getString("mechanics.support") == "point") {
    m.support = MechanicsSupport::Point;
    if (c.has("mechanics.pin_point")) {
      m.pin_point = c.getVec("mechanics.pin_point");
      if (m.pin_point->z() != 0.0)
        throw c.errorAt("mechanics.pin_point",
                        "a planar tissue's point has z = 0, got " + formatNumber(m.pin_point->z()));
    }
  } else {
    m.support = MechanicsSupport::Region;
    const std::string side = c.getString("mechanics.fixed_region");
    m.fixed_side = static_cast<int>(std::find(sideNames().begin(), sideNames().end(), side) - sideNames().begin());
  }
  return m;
}

void addMechanicsStage(const MechanicsSpec& spec, StageList& stages) {
  if (spec.enabled) stages.add(std::make_unique<MechanicsStage>(spec));
}

}  // namespace tessella::sim
