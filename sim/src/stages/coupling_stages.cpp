// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/stages/coupling_stages.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "../config/exact_text.hpp"
#include "coupling_cells.hpp"
#include "reaction_terms.hpp"
#include "tessella/io/field_state.hpp"
#include "tessella/mesh/field_transfer.hpp"
#include "tessella/solvers/compartment_transport.hpp"
#include "tessella/solvers/elasticity.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::sim {

const std::vector<std::string>& boundaryRegionNames() {
  static const std::vector<std::string> names = {"all", "x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  return names;
}

const char* boundaryRegionName(BoundaryRegion region) {
  return boundaryRegionNames()[static_cast<std::size_t>(region)].c_str();
}

bool SolveSchedule::due(const StepContext& context) {
  if (!start_) {
    start_ = context.time;
    // A run restarted between two solves counts from the last solve before
    // the snapshot, as the uninterrupted run does: solves end the clock
    // steps that are multiples of every_, and solved() records time + dt.
    const std::size_t last_solve = context.clock_step - context.clock_step % every_;
    last_ = context.time;
    if (last_solve != context.clock_step && last_solve > 0) {
      const auto clock = [&](std::size_t m) { return context.clock_origin + static_cast<double>(m) * context.clock_dt; };
      last_ = clock(last_solve - 1) + (clock(last_solve) - clock(last_solve - 1));
    } else if (last_solve != context.clock_step) {
      last_ = context.clock_origin;
    }
  }
  return (context.clock_step + 1) % every_ == 0;
}

namespace {
// Solver steps of equal length covering `elapsed` (one when no dt is given).
double stepLength(const std::optional<double>& dt, double elapsed) {
  return dt ? std::min(*dt, elapsed) : elapsed;
}
}  // namespace

// --- diffusion ---------------------------------------------------------------

DiffusionStage::DiffusionStage(DiffusionSpec spec, std::shared_ptr<FieldMesh> mesh)
    : MeshFieldStage(std::move(mesh)), spec_(std::move(spec)), schedule_(spec_.every), total_(spec_.species.size(), 0.0) {
  if (spec_.hasReaction()) {
    std::vector<std::string> names, expressions, keys;
    for (const SpeciesSpec& sp : spec_.species) {
      names.push_back(sp.name);
      expressions.push_back(sp.reaction);
      keys.push_back(sp.key_prefix + ".reaction");
    }
    reaction_ = std::make_shared<detail::ReactionTerms>(names, expressions, keys);  // compiled once per stage
  }
}

std::vector<std::string> DiffusionStage::cellPropertiesWritten() const {
  std::vector<std::string> names;
  for (const SpeciesSpec& sp : spec_.species) names.insert(names.end(), {sp.name, sp.name + "_amount"});
  return names;
}

void DiffusionStage::prepare(Tissue& tissue, double /*time*/) {
  // Source cells are chosen once, on the initial tissue.
  for (const SpeciesSpec& sp : spec_.species)
    detail::markCells(tissue, sp.name + "_source", sp.source.lineage_ids, sp.source.center, sp.source.radius,
                      sp.key_prefix + ".source.cells");
  // A restart continues the saved mesh and fields; the snapshot's tissue
  // already holds the cell averages and amounts the run had.
  if (restart_ && !spec_.fresh_restart && restore(tissue)) return;
  if (spec_.steady) return;  // the first solve gives the fields
  mesh_->update(tissue);
  for (const SpeciesSpec& sp : spec_.species)
    mesh_->setField(sp.name, Eigen::VectorXd::Constant(mesh_->mesh().numNodes(), sp.initial), true);
  storeCellValues(tissue);
}

void DiffusionStage::storeCellValues(Tissue& tissue) {
  // Cell averages (copied to daughters until the next solve) and amounts
  // (split by measure) as cell properties, for the tissue series and gates.
  const std::vector<double>& measure = mesh_->cellMeasures();
  for (const SpeciesSpec& sp : spec_.species) {
    const std::vector<double> amount = mesh_->cellIntegrals(mesh_->field(sp.name));
    auto& average = detail::doubleColumn(tissue, sp.name, DivisionPolicy::Copy);
    auto& amounts = detail::doubleColumn(tissue, sp.name + "_amount", DivisionPolicy::SplitByMeasure);
    for (CellId c : tissue.cells()) {
      const std::size_t i = c.index();
      amounts[c] = i < amount.size() ? amount[i] : 0.0;
      average[c] = i < measure.size() && measure[i] > 0 ? amount[i] / measure[i] : 0.0;
    }
  }
}

void DiffusionStage::apply(Tissue& tissue, const StepContext& context) {
  if (!schedule_.due(context)) return;
  const double elapsed = schedule_.elapsed(context);
  mesh_->update(tissue);
  const mesh::FeMesh& mesh = mesh_->mesh();
  for (const SpeciesSpec& sp : spec_.species)
    if (!mesh_->hasField(sp.name))
      mesh_->setField(sp.name, Eigen::VectorXd::Constant(mesh.numNodes(), sp.initial), true);

  if (!solver_ || solver_mesh_version_ != mesh_->version()) {
    std::vector<solvers::Species> all;
    for (const SpeciesSpec& sp : spec_.species) {
      const std::string& p = sp.key_prefix;
      solvers::Species s;
      s.name = sp.name;
      s.diffusivity = detail::perCell(tissue, sp.diffusivity, spec_.type_property, "diffusion");
      s.decay = detail::perCell(tissue, sp.decay, spec_.type_property, "diffusion");
      s.production = detail::perCell(tissue, sp.production, spec_.type_property, "diffusion");
      const std::vector<bool> source = detail::marked(tissue, sp.name + "_source");
      for (std::size_t c = 0; c < source.size(); ++c)
        if (source[c]) s.production[static_cast<Eigen::Index>(c)] += sp.source.rate;
      for (const RegionValue& r : sp.dirichlet)
        s.dirichlet.push_back({detail::regionFacets(mesh, r.region, p + ".dirichlet"), r.value, {}});
      for (const RegionValue& r : sp.flux)
        s.flux.push_back({detail::regionFacets(mesh, r.region, p + ".flux"), r.value, {}});
      for (const RegionValue& r : sp.robin)
        s.robin.push_back({detail::regionFacets(mesh, r.region, p + ".robin"), r.value, sp.robin_exterior});
      all.push_back(std::move(s));
    }
    solvers::DiffusionOptions options;
    options.scheme = spec_.scheme;
    options.mass = spec_.mass;
    solver_.emplace(mesh, std::move(all), options);
    if (reaction_)
      solver_->setReaction([terms = reaction_](std::span<const double> u, std::span<double> rate) {
        terms->evaluate(u, rate);
      });
    solver_mesh_version_ = mesh_->version();
  }
  solver_->setTime(context.time + context.dt - elapsed);
  for (std::size_t k = 0; k < spec_.species.size(); ++k)
    solver_->setState(static_cast<int>(k), mesh_->field(spec_.species[k].name));
  if (spec_.steady) {
    solver_->setTime(context.time + context.dt);
    solver_->solveSteady();
  } else if (elapsed > 0) {
    solver_->advance(elapsed, stepLength(spec_.dt, elapsed));
  }
  for (std::size_t k = 0; k < spec_.species.size(); ++k) {
    const auto col = static_cast<Eigen::Index>(k);
    mesh_->setField(spec_.species[k].name, solver_->state().col(col), true);
    total_[k] = solver_->totalAmount(static_cast<int>(k));
  }
  storeCellValues(tissue);
  schedule_.solved(context);
}

namespace {
std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::string hex(std::uint32_t x) {
  char text[16];
  std::snprintf(text, sizeof text, "%08x", x);
  return text;
}
}  // namespace

void DiffusionStage::saveState(const Tissue& tissue, const std::string& snapshot_path, const io::VtuOptions& options,
                               io::RunState& state) const {
  std::vector<std::string> names, totals;
  for (const SpeciesSpec& sp : spec_.species) names.push_back(sp.name);
  for (double total : total_) totals.push_back(formatNumber(total));
  state["diffusion.species"] = joined(names);
  state["diffusion.mode"] = spec_.steady ? "steady" : "transient";
  state["diffusion.total"] = joined(totals);
  if (!mesh_->hasMesh()) {  // a steady species before its first solve
    state["diffusion.fields"] = "";
    return;
  }
  // The cells as the field state numbers them: the meshed tissue's live
  // cells in slot order, as its snapshot would number them.
  const std::vector<std::int64_t>& lineage = mesh_->meshedLineage();
  std::vector<int> rank(lineage.size(), -1);
  io::FieldState saved;
  for (std::size_t c = 0; c < lineage.size(); ++c)
    if (lineage[c] >= 0) {
      rank[c] = static_cast<int>(saved.cell_lineage.size());
      saved.cell_lineage.push_back(lineage[c]);
    }
  saved.mesh = mesh_->mesh();
  for (Eigen::Index e = 0; e < saved.mesh.element_cell.size(); ++e)
    saved.mesh.element_cell[e] = rank[static_cast<std::size_t>(saved.mesh.element_cell[e])];
  saved.fields = mesh_->fields();
  std::vector<std::string> carried;
  for (const auto& [name, values] : saved.fields)
    if (mesh_->carried(name)) carried.push_back(name);
  const std::string path = io::fieldStatePath(snapshot_path);
  const std::uint32_t crc = io::writeFieldState(saved, path, options);
  state["diffusion.fields"] = std::filesystem::path(path).filename().string();
  state["diffusion.fields.crc32"] = hex(crc);
  state["diffusion.fields.current"] = mesh_->meshes(tissue) ? "1" : "0";
  state["diffusion.fields.carried"] = joined(carried);
}

void DiffusionStage::continueFrom(const std::string& snapshot_path, const io::RunState& state) {
  restart_ = Restart{snapshot_path, state};
}

bool DiffusionStage::restore(const Tissue& tissue) {
  const std::string& snapshot = restart_->snapshot;
  const io::RunState& state = restart_->state;
  const auto value = [&](const std::string& key) -> const std::string* {
    const auto it = state.find(key);
    return it == state.end() ? nullptr : &it->second;
  };
  const std::string fresh = " (set diffusion.restart: fresh to start the species from their initial values instead)";
  const std::string* file = value("diffusion.fields");
  if (!file) {
    // A tissue file that is not a run's snapshot: an initial tissue.
    if (!value("clock.step")) return false;
    throw InputError("snapshot '" + snapshot +
                     "' holds no state of the diffusion stage: its run had no diffusion section, or it was "
                     "written without it (by an older Tessella, or by io::writeTissueVtu instead of "
                     "Simulation::writeSnapshot)" + fresh);
  }
  std::vector<std::string> names;
  for (const SpeciesSpec& sp : spec_.species) names.push_back(sp.name);
  const std::string* species = value("diffusion.species");
  const std::string* mode = value("diffusion.mode");
  const std::string* totals = value("diffusion.total");
  const std::string want_mode = spec_.steady ? "steady" : "transient";
  if (!species || words(*species) != names)
    throw InputError("snapshot '" + snapshot + "' continues the species '" + (species ? *species : "") +
                     "', the config has '" + joined(names) + "'" + fresh);
  if (!mode || *mode != want_mode)
    throw InputError("snapshot '" + snapshot + "' was written by a run with diffusion.mode " +
                     (mode ? *mode : "?") + ", the config has " + want_mode + fresh);
  const std::vector<std::string> total_words = totals ? words(*totals) : std::vector<std::string>{};
  std::vector<double> total(names.size(), 0.0);
  bool totals_ok = total_words.size() == names.size();
  for (std::size_t k = 0; totals_ok && k < names.size(); ++k)
    totals_ok = detail::parseExact(total_words[k], total[k]);
  if (!totals_ok)
    throw InputError("snapshot '" + snapshot + "': its run state holds diffusion.total = '" + (totals ? *totals : "") +
                     "', not one number per species");
  total_ = total;
  if (file->empty()) return true;  // no mesh yet (a steady species before its first solve)

  const std::string path = (std::filesystem::path(snapshot).parent_path() / *file).string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError("'" + path + "', the diffusion state written beside snapshot '" + snapshot +
                     "', is missing" + fresh);
  const std::string* crc = value("diffusion.fields.crc32");
  const std::string actual = hex(io::fileChecksum(path));
  if (!crc || *crc != actual)
    throw InputError("'" + path + "' is not the diffusion state written with snapshot '" + snapshot +
                     "': its CRC-32 is " + actual + ", the snapshot's run state records " + (crc ? *crc : "none") +
                     " (a file of another step or run, or damaged)" + fresh);
  io::FieldState saved = io::readFieldState(path);
  if (saved.mesh.dim != tissue.dim())
    throw InputError("'" + path + "' holds a mesh of dimension " + std::to_string(saved.mesh.dim) +
                     " for a tissue of dimension " + std::to_string(tissue.dim()));
  for (const std::string& name : names)
    if (!saved.fields.count(name))
      throw InputError("'" + path + "' has no field '" + name + "' (it has " + std::to_string(saved.fields.size()) +
                       " fields)");
  const std::string* current = value("diffusion.fields.current");
  const bool is_current = current && *current == "1";
  if (is_current) {
    // The mesh was made of the snapshot's tissue itself: the same cells in
    // the same order.
    const std::vector<std::int64_t> lineage = mesh::cellLineage(tissue);
    std::vector<std::int64_t> live;
    for (std::int64_t id : lineage)
      if (id >= 0) live.push_back(id);
    if (live != saved.cell_lineage)
      throw InputError("'" + path + "' was meshed from " + std::to_string(saved.cell_lineage.size()) +
                       " cells that are not the snapshot's " + std::to_string(live.size()) +
                       " cells (lineage ids differ): not the state of snapshot '" + snapshot + "'");
    if (lineage.size() != live.size())
      throw InputError("snapshot '" + snapshot + "' read back with removed cells; cannot continue its mesh");
  }
  const std::string* carried = value("diffusion.fields.carried");
  std::set<std::string> carried_names;
  for (const std::string& name : carried ? words(*carried) : names) carried_names.insert(name);
  try {
    mesh_->restore(std::move(saved.mesh), std::move(saved.cell_lineage), std::move(saved.fields), carried_names,
                   is_current ? &tissue : nullptr);
  } catch (const InputError& e) {
    throw InputError("'" + path + "': " + e.what());
  }
  return true;
}

// --- compartments -------------------------------------------------------------

CompartmentStage::CompartmentStage(CompartmentSpec spec) : spec_(std::move(spec)), schedule_(spec_.every) {}

std::vector<std::string> CompartmentStage::cellPropertiesWritten() const {
  return {spec_.field, spec_.field + "_amount"};
}

void CompartmentStage::prepare(Tissue& tissue, double /*time*/) {
  const std::string& f = spec_.field;
  {
    detail::markCells(tissue, f + "_source", spec_.source.lineage_ids, spec_.source.center, spec_.source.radius,
                      "compartments.source.cells");
    if (!spec_.polar_all)
      detail::markCells(tissue, f + "_polar", spec_.polar_cells, Vec3::Zero(), 0.0, "compartments.polar.cells");
    // The amount is the state: split by measure at division, so divisions
    // conserve it. A tissue read back from a snapshot of the run has it.
    if (tissue.cellProperties().has(f + "_amount") && tissue.cellProperties().has(f)) return;
    auto& amount = detail::doubleColumn(tissue, f + "_amount", DivisionPolicy::SplitByMeasure);
    auto& conc = detail::doubleColumn(tissue, f, DivisionPolicy::Copy);
    for (CellId c : tissue.cells()) {
      amount[c] = spec_.initial * cellMeasure(tissue, c);
      conc[c] = spec_.initial;
    }
  }
}

void CompartmentStage::apply(Tissue& tissue, const StepContext& context) {
  const std::string& f = spec_.field;
  if (!schedule_.due(context)) return;
  const double elapsed = schedule_.elapsed(context);

  // Wall lengths (2D) or areas (3D), cell measures and centroids.
  GeometryCache own;
  GeometryCache& geometry = context.geometry ? *context.geometry : own;
  geometry.require(tissue, tissue.dim() == 2 ? kCellMeasures | GeometryQuantity::EdgeLengths : kCellMeasures);
  std::vector<int> index(tissue.cellSlots(), -1);
  std::vector<CellId> cells;
  for (CellId c : tissue.cells()) {
    index[c.index()] = static_cast<int>(cells.size());
    cells.push_back(c);
  }
  const auto n = static_cast<Eigen::Index>(cells.size());
  const Eigen::VectorXd perm = detail::perCell(tissue, spec_.permeability, spec_.type_property, "compartments");
  const Eigen::VectorXd decay = detail::perCell(tissue, spec_.decay, spec_.type_property, "compartments");
  const Eigen::VectorXd prod = detail::perCell(tissue, spec_.production, spec_.type_property, "compartments");
  const std::vector<bool> source = detail::marked(tissue, f + "_source");
  const std::vector<bool> pumps = spec_.polar_all ? std::vector<bool>(tissue.cellSlots(), true)
                                                  : detail::marked(tissue, f + "_polar");
  solvers::CompartmentNetwork net;
  net.volume.resize(n);
  net.decay.resize(n);
  net.production.resize(n);
  auto& amount = detail::doubleColumn(tissue, f + "_amount", DivisionPolicy::SplitByMeasure);
  auto& conc = detail::doubleColumn(tissue, f, DivisionPolicy::Copy);
  Eigen::VectorXd c(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const CellId cell = cells[static_cast<std::size_t>(k)];
    const std::size_t i = cell.index();
    net.volume[k] = geometry.cellMeasure(tissue, cell);
    net.decay[k] = decay[static_cast<Eigen::Index>(i)];
    net.production[k] = prod[static_cast<Eigen::Index>(i)] + (source[i] ? spec_.source.rate : 0.0);
    c[k] = amount[cell] / net.volume[k];
  }
  for (WallId w : tissue.walls()) {
    const std::vector<CellId> two = tissue.wallCells(w);
    if (two.size() != 2) continue;
    const CellId a = two[0], b = two[1];
    solvers::CompartmentWall wall;
    wall.cell_i = index[a.index()];
    wall.cell_j = index[b.index()];
    wall.area = tissue.dim() == 2 ? geometry.edge_length[w.index()] : geometry.face_area[w.index()];
    wall.permeability = std::min(perm[a.index()], perm[b.index()]);
    if (spec_.polar_rate > 0) {
      const double along = (geometry.cellCentroid(tissue, b) - geometry.cellCentroid(tissue, a)).dot(spec_.polar_direction);
      if (along > 0 && pumps[a.index()]) wall.polar_ij = spec_.polar_rate;
      if (along < 0 && pumps[b.index()]) wall.polar_ji = spec_.polar_rate;
    }
    net.walls.push_back(wall);
  }
  const Eigen::VectorXd volume = net.volume;
  solvers::CompartmentTransport transport(std::move(net), spec_.scheme);
  if (elapsed > 0) transport.advance(c, elapsed, stepLength(spec_.dt, elapsed));
  for (Eigen::Index k = 0; k < n; ++k) {
    const CellId cell = cells[static_cast<std::size_t>(k)];
    conc[cell] = c[k];
    amount[cell] = c[k] * volume[k];
  }
  schedule_.solved(context);
}

// --- elasticity ----------------------------------------------------------------

ElasticityStage::ElasticityStage(ElasticitySpec spec, std::shared_ptr<FieldMesh> mesh)
    : MeshFieldStage(std::move(mesh)), spec_(std::move(spec)), schedule_(spec_.every) {}

const std::vector<std::string>& ElasticityStage::stressPropertyNames() {
  static const std::vector<std::string> names = {"stress_xx", "stress_yy", "stress_zz",           "stress_yz",
                                                 "stress_xz", "stress_xy", "stress_max_principal"};
  return names;
}

void ElasticityStage::apply(Tissue& tissue, const StepContext& context) {
  if (!schedule_.due(context)) return;
  mesh_->update(tissue);
  const mesh::FeMesh& mesh = mesh_->mesh();
  if (spec_.model == solvers::ElasticModel::Solid && mesh.dim != 3)
    throw InputError("elasticity.model: solid needs a 3D tissue; use plane_stress or plane_strain for 2D");
  if (spec_.model != solvers::ElasticModel::Solid && mesh.dim != 2)
    throw InputError("elasticity.model: plane models need a 2D tissue; use solid for 3D");
  solvers::ElasticityProblem p;
  p.model = spec_.model;
  p.young = detail::perCell(tissue, spec_.young, spec_.type_property, "elasticity");
  p.poisson = detail::perCell(tissue, spec_.poisson, spec_.type_property, "elasticity");
  p.thickness = spec_.thickness;
  for (const auto& [region, fixed] : spec_.fixed)
    p.displacement.push_back({detail::regionFacets(mesh, region, "elasticity.fixed"), {}, fixed, Eigen::Vector3d::Zero()});
  if (spec_.stretch_region) {
    const int axis = (static_cast<int>(*spec_.stretch_region) - 1) / 2;
    solvers::DisplacementCondition d{detail::regionFacets(mesh, *spec_.stretch_region, "elasticity.stretch_region"), {},
                            {false, false, false}, Eigen::Vector3d::Zero()};
    d.fixed[static_cast<std::size_t>(axis)] = true;
    d.value[axis] = spec_.stretch;
    p.displacement.push_back(std::move(d));
  }
  if (spec_.traction_region)
    p.traction.push_back({detail::regionFacets(mesh, *spec_.traction_region, "elasticity.traction_region"),
                          spec_.traction});
  const solvers::ElasticityResult r = solvers::solveElasticity(mesh, p);
  const char* axes[] = {"displacement_x", "displacement_y", "displacement_z"};
  for (int a = 0; a < 3; ++a) mesh_->setField(axes[a], r.displacement.col(a), false);
  const std::vector<std::string>& names = stressPropertyNames();
  for (int k = 0; k < 6; ++k) {
    auto& column = detail::doubleColumn(tissue, names[static_cast<std::size_t>(k)], DivisionPolicy::Copy);
    for (CellId c : tissue.cells())
      column[c] = static_cast<Eigen::Index>(c.index()) < r.cell_stress.rows() ? r.cell_stress(c.index(), k) : 0.0;
  }
  auto& top = detail::doubleColumn(tissue, names[6], DivisionPolicy::Copy);
  for (CellId c : tissue.cells())
    top[c] = static_cast<Eigen::Index>(c.index()) < r.principal_stress.rows() ? r.principal_stress(c.index(), 2) : 0.0;
  schedule_.solved(context);
}

}  // namespace tessella::sim
