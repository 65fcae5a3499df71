// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/stages/growth_stages.hpp"

#include <stdexcept>
#include <typeindex>

namespace tessella::sim {

GrowthStage::GrowthStage(std::shared_ptr<const growth::VelocityField> field, growth::GrowthOptions options)
    : integrator_(std::make_shared<growth::GrowthIntegrator>(std::move(field), std::move(options))) {}

GrowthStage::GrowthStage(std::shared_ptr<growth::GrowthIntegrator> integrator) : integrator_(std::move(integrator)) {
  if (!integrator_) throw std::invalid_argument("GrowthStage: null integrator");
}

void GrowthStage::apply(Tissue& tissue, const StepContext& context) {
  // The integrator runs from the tissue's clock; the Simulation keeps it at
  // the step's start time.
  tissue.setTime(context.time);
  if (context.geometry)
    integrator_->step(tissue, context.dt, *context.geometry);
  else
    integrator_->step(tissue, context.dt);
}

namespace {
growth::DivisionOptions withGate(growth::DivisionOptions options, const std::optional<DivisionGate>& gate) {
  if (!gate) return options;
  // The field is a cell property a solver stage writes after each solve;
  // until it exists (before the first solve) the gate stays closed.
  options.gate = [name = gate->field, above = gate->above](const Tissue& t, CellId c) {
    const PropertyColumnBase* column = t.cellProperties().find(name);
    if (!column || column->type() != std::type_index(typeid(double))) return false;
    return t.cellProperties().get<double>(name)[c] > above;
  };
  return options;
}
}  // namespace

DivisionStage::DivisionStage(std::shared_ptr<const growth::DivisionRule> rule, growth::SizeThreshold threshold,
                             growth::DivisionOptions options, std::optional<DivisionGate> gate)
    : scheduler_(std::make_shared<growth::DivisionScheduler>(std::move(threshold), std::move(rule),
                                                             withGate(std::move(options), gate))) {}

DivisionStage::DivisionStage(std::shared_ptr<growth::DivisionScheduler> scheduler) : scheduler_(std::move(scheduler)) {
  if (!scheduler_) throw std::invalid_argument("DivisionStage: null scheduler");
}

void DivisionStage::apply(Tissue& tissue, const StepContext& context) {
  tissue.setTime(context.end_time);  // daughters are born at the end of the step
  GeometryCache& geometry = context.geometry ? *context.geometry : geometry_;  // shared: fresh after growth
  const growth::DivisionReport report = context.rng ? scheduler_->step(tissue, geometry, *context.rng)
                                                    : scheduler_->step(tissue, geometry);
  divisions_ += report.divided.size();
  skipped_ += report.skipped.size();
}

}  // namespace tessella::sim
