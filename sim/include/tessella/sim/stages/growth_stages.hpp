#pragma once
// The growth and division stages of a Simulation (see stage.hpp):
//   GrowthStage    moves every vertex with the velocity field over the step
//                  (growth::GrowthIntegrator);
//   DivisionStage  divides the cells over their size threshold
//                  (growth::DivisionScheduler), drawing from the run's
//                  random stream; daughters are born at the step's end time.

#include <cstddef>
#include <memory>

#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/sim/sections/growth_section.hpp"
#include "tessella/sim/stages/stage.hpp"

namespace tessella::sim {

class GrowthStage final : public Stage {
 public:
  explicit GrowthStage(const GrowthSpec& spec);
  std::string name() const override { return "growth"; }
  void apply(Tissue& tissue, const StepContext& context) override;
  const growth::GrowthIntegrator& integrator() const { return integrator_; }

 private:
  growth::GrowthIntegrator integrator_;
};

class DivisionStage final : public Stage {
 public:
  explicit DivisionStage(const DivisionSpec& spec);
  std::string name() const override { return "division"; }
  void apply(Tissue& tissue, const StepContext& context) override;
  /// Totals over the run so far.
  std::size_t divisions() const { return divisions_; }
  std::size_t skipped() const { return skipped_; }

 private:
  growth::DivisionScheduler scheduler_;
  GeometryCache geometry_;  // when the step context shares none
  std::size_t divisions_ = 0, skipped_ = 0;
};

}  // namespace tessella::sim
