// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The growth and division stages of a Simulation (see stage.hpp):
//   GrowthStage    moves every vertex with the velocity field over the step
//                  (growth::GrowthIntegrator);
//   DivisionStage  divides the cells over their size threshold
//                  (growth::DivisionScheduler), drawing from the run's
//                  random stream; daughters are born at the step's end time.
// Both are built from growth/ objects (the growth section builds them from
// its keys; a C++ or Python model from its own field, rule and threshold),
// or share an integrator / scheduler a model built and keeps using.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "tessella/growth/division_rule.hpp"
#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/growth/size_threshold.hpp"
#include "tessella/growth/velocity_field.hpp"
#include "tessella/sim/stages/stage.hpp"

namespace tessella::sim {

class GrowthStage final : public Stage {
 public:
  GrowthStage(std::shared_ptr<const growth::VelocityField> field, growth::GrowthOptions options = {});
  /// Steps with `integrator`, shared with its builder.
  explicit GrowthStage(std::shared_ptr<growth::GrowthIntegrator> integrator);
  std::string name() const override { return "growth"; }
  /// Throws what the integrator throws, the tissue left as it was.
  void apply(Tissue& tissue, const StepContext& context) override;
  const growth::GrowthIntegrator& integrator() const { return *integrator_; }

 private:
  std::shared_ptr<growth::GrowthIntegrator> integrator_;
};

/// A cell divides only where the double cell property `field` (a solver
/// field's cell average) exceeds `above`; until the property exists (before
/// the first solve) no cell divides.
struct DivisionGate {
  std::string field;
  double above = 0.0;
};

class DivisionStage final : public Stage {
 public:
  /// A gate replaces options.gate.
  DivisionStage(std::shared_ptr<const growth::DivisionRule> rule, growth::SizeThreshold threshold,
                growth::DivisionOptions options = {}, std::optional<DivisionGate> gate = std::nullopt);
  /// Divides with `scheduler`, shared with its builder.
  explicit DivisionStage(std::shared_ptr<growth::DivisionScheduler> scheduler);
  std::string name() const override { return "division"; }
  void apply(Tissue& tissue, const StepContext& context) override;
  /// Totals over the run so far.
  std::size_t divisions() const { return divisions_; }
  std::size_t skipped() const { return skipped_; }

 private:
  std::shared_ptr<growth::DivisionScheduler> scheduler_;
  GeometryCache geometry_;  // when the step context shares none
  std::size_t divisions_ = 0, skipped_ = 0;
};

}  // namespace tessella::sim
