// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/stages/network_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>

#include "coupling_cells.hpp"
#include "tessella/io/wall_vtu.hpp"
#include "tessella/networks/initial_values.hpp"
#include "tessella/networks/network_graph.hpp"
#include "tessella/networks/network_system.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::sim {

NetworkStage::NetworkStage(NetworkSpec spec) : spec_(std::move(spec)), schedule_(spec_.every) {
  spec_.model.validate();
  const std::size_t S = spec_.model.species.size();
  if (spec_.initial.empty()) spec_.initial.assign(S, "0");
  if (spec_.noise.empty()) spec_.noise.assign(S, 0.0);
  if (spec_.initial.size() != S || spec_.noise.size() != S)
    throw InputError("network: one initial value and one noise amplitude per species");
  for (std::size_t s = 0; s < S; ++s) {
    try {
      networks::checkInitialExpression(spec_.initial[s], spec_.model.parameters);
    } catch (const InputError& e) {
      throw InputError("network: species '" + spec_.model.species[s].name + "': " + e.what());
    }
  }
  if (spec_.every < 1) throw InputError("network: every must be >= 1");
  if (spec_.primordia.enabled()) {
    if (spec_.model.speciesIndex(spec_.primordia.species) < 0)
      throw InputError("network: primordia species '" + spec_.primordia.species + "' is not a species");
    spec_.primordia.options.validate();
  }
}

namespace {

// The amounts y[k S + s] of `cells` (species s), from the species' `_amount` columns.
std::vector<double> cellAmounts(const Tissue& tissue, const networks::NetworkModel& model,
                                const std::vector<CellId>& cells) {
  const std::size_t S = model.species.size();
  std::vector<double> y(S * cells.size());
  for (std::size_t s = 0; s < S; ++s) {
    const auto& amount = tissue.cellProperties().get<double>(model.species[s].name + "_amount");
    for (std::size_t k = 0; k < cells.size(); ++k) y[k * S + s] = amount[cells[k]];
  }
  return y;
}

const std::string kPrimordiaKey = "network.primordia";
const std::string kPinKey = "network.pin";

PropertyColumn<double>& pinWallColumn(Tissue& tissue, const std::string& name, double initial) {
  PropertyStore& store = tissue.wallProperties();
  if (const PropertyColumnBase* c = store.find(name); c && c->type() != std::type_index(typeid(double)))
    throw InputError("wall property '" + name + "' exists and does not hold numbers (double)");
  if (!store.has(name)) store.add<double>(name, initial, DivisionPolicy::Copy);
  return store.get<double>(name);
}

// Whether the first of a wall's two saved densities is on its positive side: the first is on the side of
// the cell with the smaller lineage id (a boundary wall: of its cell). Lineage ids survive a snapshot, the
// wall's orientation need not.
bool firstIsPositive(const Tissue& tissue, WallId w) {
  const std::vector<CellId> two = tissue.wallCells(w);
  if (two.empty()) return true;
  CellId a = two[0];
  if (two.size() == 2 && tissue.lineageId(two[1]) < tissue.lineageId(a)) a = two[1];
  return networks::onPositiveSide(tissue, w, a);
}

PropertyColumn<int>& primordiumColumn(Tissue& tissue) {
  PropertyStore& store = tissue.cellProperties();
  if (const PropertyColumnBase* c = store.find(kPrimordiumProperty); c && c->type() != std::type_index(typeid(int)))
    throw InputError(std::string("cell property '") + kPrimordiumProperty + "' exists and does not hold ints");
  if (!store.has(kPrimordiumProperty)) store.add<int>(kPrimordiumProperty, 0, DivisionPolicy::Copy);
  return store.get<int>(kPrimordiumProperty);
}
}  // namespace

void NetworkStage::detectPrimordia(Tissue& tissue, const std::vector<CellId>& cells,
                                   const networks::NetworkSystem& system, const std::vector<double>& y, double time) {
  const networks::NetworkGraph& graph = system.graph();
  const std::size_t S = system.numSpecies();
  const auto s = static_cast<std::size_t>(spec_.model.speciesIndex(spec_.primordia.species));
  std::vector<double> c(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) c[k] = y[k * S + s] / graph.measure[k];
  auto& id = primordiumColumn(tissue);
  // Each existing primordium is where its cells are now: the mean centroid of
  // the cells carrying its id (the first cell and its descendants).
  std::vector<Vec3> sum(primordia_.size(), Vec3::Zero());
  std::vector<int> count(primordia_.size(), 0);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const int p = id[cells[k]];
    if (p < 1 || static_cast<std::size_t>(p) > primordia_.size()) continue;
    sum[static_cast<std::size_t>(p) - 1] += graph.centroid[k];
    ++count[static_cast<std::size_t>(p) - 1];
  }
  std::vector<Vec3> existing;
  for (std::size_t p = 0; p < sum.size(); ++p)
    if (count[p] > 0) existing.push_back(sum[p] / count[p]);
  const networks::PrimordiumOptions& o = spec_.primordia.options;
  for (int k : networks::findPrimordia(graph, c, o, existing)) {
    const auto u = static_cast<std::size_t>(k);
    PrimordiumRecord r;
    r.id = static_cast<int>(primordia_.size()) + 1;
    r.time = time;
    r.lineage = tissue.lineageId(cells[u]);
    r.position = graph.centroid[u];
    const networks::AxialPosition a = networks::axialPosition(r.position, o.apex, o.axis);
    r.angle_deg = a.angle_deg;
    r.radius = a.radius;
    r.distance = a.distance;
    r.divergence_deg = primordia_.empty() ? std::numeric_limits<double>::quiet_NaN()
                                          : networks::divergenceDeg(primordia_.back().angle_deg, a.angle_deg);
    id[cells[u]] = r.id;
    primordia_.push_back(r);
  }
}

std::string NetworkStage::pinWallProperty(const std::string& species, bool positive_side) {
  return species + (positive_side ? "_pin_pos" : "_pin_neg");
}

void NetworkStage::writePinWalls(const Tissue& tissue, const std::string& snapshot_path,
                                 const io::VtuOptions& options) const {
  GeometryCache geometry;
  std::vector<CellId> cells;
  std::vector<std::vector<networks::InterfaceWall>> walls;
  networks::NetworkGraph graph =
      networks::networkGraph(tissue, geometry, spec_.model.cell_properties, &cells, &walls);
  networks::NetworkSystem system(spec_.model, std::move(graph));
  const std::vector<double> y = readState(tissue, cells, walls, system, cellAmounts(tissue, spec_.model, cells));
  const std::vector<networks::PinSides> density = system.pinDensity(y);
  // Per live wall in slot order; i is the cell with the smaller lineage id.
  std::vector<int> slot(tissue.topology().slots(tissue.dim() - 1), -1);
  int count = 0;
  for (WallId w : tissue.walls()) slot[w.index()] = count++;
  const std::size_t n = tissue.numWalls();
  io::WallArrays a;
  auto& pin_ij = a.scalars["pin_ij"] = std::vector<double>(n, 0.0);
  auto& pin_ji = a.scalars["pin_ji"] = std::vector<double>(n, 0.0);
  auto& cell_i = a.scalars["cell_i"] = std::vector<double>(n, -1.0);
  auto& cell_j = a.scalars["cell_j"] = std::vector<double>(n, -1.0);
  auto& net = a.vectors["pin_net"] = std::vector<Vec3>(n, Vec3::Zero());
  for (WallId w : tissue.walls()) {  // boundary walls: their one cell
    const std::vector<CellId> two = tissue.wallCells(w);
    if (!two.empty()) cell_i[static_cast<std::size_t>(slot[w.index()])] = static_cast<double>(tissue.lineageId(two[0]));
  }
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const networks::NetworkInterface& f = system.graph().interfaces[k];
    const CellId gi = cells[static_cast<std::size_t>(f.cell_i)], gj = cells[static_cast<std::size_t>(f.cell_j)];
    const bool flip = tissue.lineageId(gj) < tissue.lineageId(gi);  // the graph's cell_j is the file's i
    const double ij = flip ? density[k].ji : density[k].ij, ji = flip ? density[k].ij : density[k].ji;
    const Vec3 normal = flip ? Vec3(-f.normal) : f.normal;
    for (const networks::InterfaceWall& w : walls[k]) {
      const auto u = static_cast<std::size_t>(slot[w.wall.index()]);
      pin_ij[u] = ij;
      pin_ji[u] = ji;
      cell_i[u] = static_cast<double>(tissue.lineageId(flip ? gj : gi));
      cell_j[u] = static_cast<double>(tissue.lineageId(flip ? gi : gj));
      net[u] = (ij - ji) * normal;
    }
  }
  io::writeWallsVtu(tissue, io::besideSnapshotPath(snapshot_path, "pin"), a, options);
}

void NetworkStage::saveState(const Tissue& tissue, const std::string& snapshot_path, const io::VtuOptions& options,
                             io::RunState& state) const {
  const networks::PinTransport& pin = spec_.model.pin;
  const PropertyStore& wall_properties = tissue.wallProperties();
  if (pin.dynamic() && wall_properties.has(pinWallProperty(pin.species, true)) &&
      wall_properties.has(pinWallProperty(pin.species, false))) {
    const auto& pos = wall_properties.get<double>(pinWallProperty(pin.species, true));
    const auto& neg = wall_properties.get<double>(pinWallProperty(pin.species, false));
    std::string text;
    for (WallId w : tissue.walls()) {
      const bool first = firstIsPositive(tissue, w);
      if (!text.empty()) text += " ";
      text += formatNumber(first ? pos[w] : neg[w]) + " " + formatNumber(first ? neg[w] : pos[w]);
    }
    state[kPinKey] = text;
  }
  if (pin.enabled() && tissue.numCells() > 0) writePinWalls(tissue, snapshot_path, options);
  if (!spec_.primordia.enabled()) return;
  std::string text;
  for (const PrimordiumRecord& r : primordia_) {
    if (!text.empty()) text += ";";
    text += std::to_string(r.id) + " " + formatNumber(r.time) + " " + std::to_string(r.lineage) + " " +
            formatNumber(r.position.x()) + " " + formatNumber(r.position.y()) + " " + formatNumber(r.position.z()) +
            " " + formatNumber(r.angle_deg) + " " + formatNumber(r.radius) + " " + formatNumber(r.distance) + " " +
            (std::isnan(r.divergence_deg) ? std::string("nan") : formatNumber(r.divergence_deg));
  }
  state[kPrimordiaKey] = text;
}

void NetworkStage::restorePin(Tissue& tissue) {
  const auto& [snapshot, text] = *restart_pin_;
  const networks::PinTransport& pin = spec_.model.pin;
  std::vector<double> values;
  std::istringstream in(text);
  std::string word;
  while (in >> word) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (word.empty() || *end != '\0' || !std::isfinite(v))
      throw InputError("snapshot '" + snapshot + "': its run state " + kPinKey + " holds '" + word +
                       "', not a number");
    values.push_back(v);
  }
  if (values.size() != 2 * tissue.numWalls())
    throw InputError("snapshot '" + snapshot + "': its run state has " + std::to_string(values.size()) +
                     " PIN densities (" + kPinKey + ") for " + std::to_string(tissue.numWalls()) +
                     " walls (two each)");
  auto& pos = pinWallColumn(tissue, pinWallProperty(pin.species, true), pin.initial);
  auto& neg = pinWallColumn(tissue, pinWallProperty(pin.species, false), pin.initial);
  std::size_t k = 0;
  for (WallId w : tissue.walls()) {
    const bool first = firstIsPositive(tissue, w);
    (first ? pos : neg)[w] = values[k];
    (first ? neg : pos)[w] = values[k + 1];
    k += 2;
  }
}

void NetworkStage::continueFrom(const std::string& snapshot_path, const io::RunState& state) {
  restart_pin_.reset();
  if (const auto it = state.find(kPinKey); it != state.end() && spec_.model.pin.dynamic())
    restart_pin_ = std::make_pair(snapshot_path, it->second);
  primordia_.clear();
  if (!spec_.primordia.enabled()) return;
  const auto it = state.find(kPrimordiaKey);
  if (it == state.end()) return;  // a snapshot written without detection: start afresh
  std::stringstream all(it->second);
  std::string item;
  while (std::getline(all, item, ';')) {
    std::stringstream in(item);
    std::string f[10];
    std::size_t n = 0;
    while (n < 10 && in >> f[n]) ++n;
    std::string extra;
    auto number = [&](const std::string& t) {
      char* end = nullptr;
      const double v = std::strtod(t.c_str(), &end);
      if (t.empty() || *end != '\0') throw InputError("run state " + kPrimordiaKey + ": '" + t + "' in '" + item +
                                                      "' is not a number");
      return v;
    };
    if (n != 10 || (in >> extra))
      throw InputError("run state " + kPrimordiaKey + ": '" + item + "' is not 10 values (id time lineage x y z "
                       "angle radius distance divergence)");
    PrimordiumRecord r;
    r.id = static_cast<int>(number(f[0]));
    r.time = number(f[1]);
    r.lineage = static_cast<std::int64_t>(number(f[2]));
    r.position = Vec3(number(f[3]), number(f[4]), number(f[5]));
    r.angle_deg = number(f[6]);
    r.radius = number(f[7]);
    r.distance = number(f[8]);
    r.divergence_deg = f[9] == "nan" ? std::numeric_limits<double>::quiet_NaN() : number(f[9]);
    primordia_.push_back(r);
  }
}

std::vector<std::string> NetworkStage::cellPropertiesWritten() const {
  std::vector<std::string> out;
  for (const auto& s : spec_.model.species) {
    out.push_back(s.name);
    out.push_back(s.name + "_amount");
  }
  return out;
}

std::vector<double> NetworkStage::readState(const Tissue& tissue, const std::vector<CellId>& cells,
                                            const std::vector<std::vector<networks::InterfaceWall>>& walls,
                                            const networks::NetworkSystem& system,
                                            const std::vector<double>& amounts) const {
  std::vector<double> y(system.size(), 0.0);
  std::copy(amounts.begin(), amounts.end(), y.begin());
  const networks::PinTransport& pin = spec_.model.pin;
  if (!pin.dynamic() || cells.empty()) return y;
  const auto& pos = tissue.wallProperties().get<double>(pinWallProperty(pin.species, true));
  const auto& neg = tissue.wallProperties().get<double>(pinWallProperty(pin.species, false));
  // An interface's density on a side: its walls' (equal after every solve), or their measure-weighted mean.
  for (std::size_t k = 0; k < walls.size(); ++k)
    for (int side = 0; side < 2; ++side) {
      double sum = 0.0, measure = 0.0, first = 0.0;
      bool equal = true;
      for (std::size_t u = 0; u < walls[k].size(); ++u) {
        const networks::InterfaceWall& w = walls[k][u];
        const double v = (w.i_positive == (side == 0)) ? pos[w.wall] : neg[w.wall];
        if (u == 0) first = v;
        equal = equal && v == first;
        sum += w.measure * v;
        measure += w.measure;
      }
      y[system.pinIndex(k, side)] = equal || !(measure > 0) ? first : sum / measure;
    }
  return y;
}

void NetworkStage::writeOutputs(Tissue& tissue, const std::vector<CellId>& cells,
                                const std::vector<std::vector<networks::InterfaceWall>>& walls,
                                networks::NetworkSystem& system, const std::vector<double>& y, bool write_pin) {
  const networks::PinTransport& pin = spec_.model.pin;
  if (pin.dynamic() && write_pin) {
    auto& pos = pinWallColumn(tissue, pinWallProperty(pin.species, true), pin.initial);
    auto& neg = pinWallColumn(tissue, pinWallProperty(pin.species, false), pin.initial);
    for (std::size_t k = 0; k < walls.size(); ++k)
      for (const networks::InterfaceWall& w : walls[k]) {
        (w.i_positive ? pos : neg)[w.wall] = y[system.pinIndex(k, 0)];
        (w.i_positive ? neg : pos)[w.wall] = y[system.pinIndex(k, 1)];
      }
  }
  const std::size_t S = system.numSpecies();
  for (std::size_t s = 0; s < S; ++s) {
    const std::string& name = spec_.model.species[s].name;
    auto& amount = detail::doubleColumn(tissue, name + "_amount", DivisionPolicy::SplitByMeasure);
    auto& conc = detail::doubleColumn(tissue, name, DivisionPolicy::Copy);
    for (std::size_t k = 0; k < cells.size(); ++k) {
      amount[cells[k]] = y[system.index(k, s)];
      conc[cells[k]] = y[system.index(k, s)] / system.graph().measure[k];
    }
  }
  if (spec_.model.pin.enabled()) {
    const std::string name = spec_.model.pin.species + "_polarity";
    PropertyStore& store = tissue.cellProperties();
    if (const PropertyColumnBase* c = store.find(name); c && c->type() != std::type_index(typeid(Vec3)))
      throw InputError("cell property '" + name + "' exists and does not hold vectors (Vec3)");
    if (!store.has(name)) store.add<Vec3>(name, Vec3::Zero(), DivisionPolicy::Copy);
    auto& polarity = store.get<Vec3>(name);
    const std::vector<Vec3> p = system.polarity(y);
    for (std::size_t k = 0; k < cells.size(); ++k) polarity[cells[k]] = p[k];
  }
}

void NetworkStage::prepare(Tissue& tissue, double /*time*/) {
  // In the first snapshot already, and before the graph: the reactions may read it.
  if (spec_.primordia.enabled()) primordiumColumn(tissue);
  const networks::PinTransport& pin = spec_.model.pin;
  if (pin.dynamic()) {
    if (restart_pin_) restorePin(tissue);
    pinWallColumn(tissue, pinWallProperty(pin.species, true), pin.initial);
    pinWallColumn(tissue, pinWallProperty(pin.species, false), pin.initial);
  }
  GeometryCache geometry;
  std::vector<CellId> cells;
  std::vector<std::vector<networks::InterfaceWall>> walls;
  networks::NetworkGraph graph =
      networks::networkGraph(tissue, geometry, spec_.model.cell_properties, &cells, &walls);
  const std::size_t S = spec_.model.species.size();
  bool present = true;
  for (const auto& s : spec_.model.species)
    present = present && tissue.cellProperties().has(s.name + "_amount") && tissue.cellProperties().has(s.name);
  std::vector<double> y(S * cells.size());
  if (present) {
    // A snapshot of the run: continue from its amounts.
    for (const auto& species : spec_.model.species)
      detail::doubleColumn(tissue, species.name + "_amount", DivisionPolicy::SplitByMeasure);  // numbers?
    y = cellAmounts(tissue, spec_.model, cells);
  } else {
    std::mt19937_64 rng(spec_.noise_seed ^ 0x6e6574776f726b73ull);  // "networks"
    for (std::size_t s = 0; s < S; ++s) {
      std::vector<double> c;
      try {
        c = networks::initialConcentrations(spec_.initial[s], graph, spec_.model.parameters, spec_.noise[s], rng);
      } catch (const InputError& e) {
        throw InputError("network: species '" + spec_.model.species[s].name + "': " + e.what());
      }
      for (std::size_t k = 0; k < cells.size(); ++k) y[k * S + s] = c[k] * graph.measure[k];
    }
  }
  networks::NetworkSystem system(spec_.model, std::move(graph));
  // The walls keep their densities (a restart's, or pin.initial) until the first solve.
  writeOutputs(tissue, cells, walls, system, readState(tissue, cells, walls, system, y), false);
}

void NetworkStage::apply(Tissue& tissue, const StepContext& context) {
  if (!schedule_.due(context)) return;
  const double elapsed = schedule_.elapsed(context);
  GeometryCache own;
  GeometryCache& geometry = context.geometry ? *context.geometry : own;
  std::vector<CellId> cells;
  std::vector<std::vector<networks::InterfaceWall>> walls;
  networks::NetworkGraph graph =
      networks::networkGraph(tissue, geometry, spec_.model.cell_properties, &cells, &walls);
  for (const auto& species : spec_.model.species)
    detail::doubleColumn(tissue, species.name + "_amount", DivisionPolicy::SplitByMeasure);
  std::vector<double> amounts = cellAmounts(tissue, spec_.model, cells);
  // The system and integrator of the last solve are kept while the graph keeps its structure (no division,
  // no cell removed): only the measures are new. They compute what new ones would, bit for bit.
  if (system_ && system_->sameStructure(graph)) {
    system_->updateGraph(std::move(graph));
  } else {
    integrator_.reset();
    system_ = std::make_unique<networks::NetworkSystem>(spec_.model, std::move(graph), spec_.jacobian);
  }
  networks::NetworkSystem& system = *system_;
  std::vector<double> y = readState(tissue, cells, walls, system, amounts);
  if (elapsed > 0 && !cells.empty()) {
    if (!integrator_) integrator_ = std::make_unique<networks::NetworkIntegrator>(system, spec_.integrator);
    const double t1 = context.time + context.dt;
    integrator_->resetStatistics();
    integrator_->advance(y, t1 - elapsed, t1);
    stats_ += integrator_->statistics();
  }
  writeOutputs(tissue, cells, walls, system, y, true);
  if (spec_.primordia.enabled() && elapsed > 0) detectPrimordia(tissue, cells, system, y, context.end_time);
  schedule_.solved(context);
}

}  // namespace tessella::sim
