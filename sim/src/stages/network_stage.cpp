// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/stages/network_stage.hpp"

#include <random>

#include "coupling_cells.hpp"
#include "tessella/networks/initial_values.hpp"
#include "tessella/networks/network_graph.hpp"
#include "tessella/networks/network_system.hpp"

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
}

std::vector<std::string> NetworkStage::cellPropertiesWritten() const {
  std::vector<std::string> out;
  for (const auto& s : spec_.model.species) {
    out.push_back(s.name);
    out.push_back(s.name + "_amount");
  }
  return out;
}

void NetworkStage::writeOutputs(Tissue& tissue, const std::vector<CellId>& cells, networks::NetworkSystem& system,
                                const std::vector<double>& y) {
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
  GeometryCache geometry;
  std::vector<CellId> cells;
  networks::NetworkGraph graph = networks::networkGraph(tissue, geometry, spec_.model.cell_properties, &cells);
  const std::size_t S = spec_.model.species.size();
  bool present = true;
  for (const auto& s : spec_.model.species)
    present = present && tissue.cellProperties().has(s.name + "_amount") && tissue.cellProperties().has(s.name);
  std::vector<double> y(S * cells.size());
  if (present) {
    // A snapshot of the run: continue from its amounts.
    for (std::size_t s = 0; s < S; ++s) {
      const auto& amount = detail::doubleColumn(tissue, spec_.model.species[s].name + "_amount",
                                                DivisionPolicy::SplitByMeasure);
      for (std::size_t k = 0; k < cells.size(); ++k) y[k * S + s] = amount[cells[k]];
    }
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
  writeOutputs(tissue, cells, system, y);
}

void NetworkStage::apply(Tissue& tissue, const StepContext& context) {
  if (!schedule_.due(context)) return;
  const double elapsed = schedule_.elapsed(context);
  GeometryCache own;
  GeometryCache& geometry = context.geometry ? *context.geometry : own;
  std::vector<CellId> cells;
  networks::NetworkGraph graph = networks::networkGraph(tissue, geometry, spec_.model.cell_properties, &cells);
  const std::size_t S = spec_.model.species.size();
  std::vector<double> y(S * cells.size());
  for (std::size_t s = 0; s < S; ++s) {
    const auto& amount =
        detail::doubleColumn(tissue, spec_.model.species[s].name + "_amount", DivisionPolicy::SplitByMeasure);
    for (std::size_t k = 0; k < cells.size(); ++k) y[k * S + s] = amount[cells[k]];
  }
  networks::NetworkSystem system(spec_.model, std::move(graph), spec_.jacobian);
  if (elapsed > 0 && !cells.empty()) {
    networks::NetworkIntegrator integrator(system, spec_.integrator);
    const double t1 = context.time + context.dt;
    integrator.advance(y, t1 - elapsed, t1);
    stats_ += integrator.statistics();
  }
  writeOutputs(tissue, cells, system, y);
  schedule_.solved(context);
}

}  // namespace tessella::sim
