#include "tessella/sim/stages/growth_stages.hpp"

#include <cmath>
#include <typeindex>

namespace tessella::sim {

GrowthStage::GrowthStage(const GrowthSpec& spec) : integrator_(spec.field, spec.options) {}

void GrowthStage::apply(Tissue& tissue, const StepContext& context) {
  // The integrator runs from the tissue's clock; the Simulation keeps it at
  // the step's start time.
  tissue.setTime(context.time);
  if (context.geometry)
    integrator_.step(tissue, context.dt, *context.geometry);
  else
    integrator_.step(tissue, context.dt);
}

namespace {
growth::DivisionOptions withGate(const DivisionSpec& spec) {
  growth::DivisionOptions options = spec.options;
  if (spec.gate_field.empty()) return options;
  // The field is a cell property a solver stage writes after each solve;
  // until it exists (before the first solve) the gate stays closed.
  options.gate = [name = spec.gate_field, above = spec.gate_above](const Tissue& t, CellId c) {
    const PropertyColumnBase* column = t.cellProperties().find(name);
    if (!column || column->type() != std::type_index(typeid(double))) return false;
    return t.cellProperties().get<double>(name)[c] > above;
  };
  return options;
}
}  // namespace

DivisionStage::DivisionStage(const DivisionSpec& spec)
    : scheduler_(*spec.threshold, spec.rule, withGate(spec)) {}

void DivisionStage::apply(Tissue& tissue, const StepContext& context) {
  tissue.setTime(context.end_time);  // daughters are born at the end of the step
  GeometryCache& geometry = context.geometry ? *context.geometry : geometry_;  // shared: fresh after growth
  const growth::DivisionReport report = context.rng ? scheduler_.step(tissue, geometry, *context.rng)
                                                    : scheduler_.step(tissue, geometry);
  divisions_ += report.divided.size();
  skipped_ += report.skipped.size();
}

}  // namespace tessella::sim
