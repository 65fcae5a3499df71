#include "tessella/sim/growth_stages.hpp"

#include <cmath>

namespace tessella::sim {

GrowthStage::GrowthStage(const GrowthSpec& spec) : integrator_(spec.field, spec.options) {}

void GrowthStage::apply(Tissue& tissue, const StepContext& context) {
  // The integrator runs from the tissue's clock; the Simulation keeps it at
  // the step's start time.
  tissue.setTime(context.time);
  integrator_.step(tissue, context.dt);
}

DivisionStage::DivisionStage(const DivisionSpec& spec)
    : scheduler_(*spec.threshold, spec.rule, spec.options) {}

void DivisionStage::apply(Tissue& tissue, const StepContext& context) {
  tissue.setTime(context.time + context.dt);  // daughters are born at the end of the step
  const growth::DivisionReport report = context.rng ? scheduler_.step(tissue, geometry_, *context.rng)
                                                    : scheduler_.step(tissue, geometry_);
  divisions_ += report.divided.size();
  skipped_ += report.skipped.size();
}

}  // namespace tessella::sim
