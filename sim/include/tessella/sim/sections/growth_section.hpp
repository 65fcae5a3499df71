// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The `growth:` and `division:` sections: the velocity field that moves the
// vertices every step (and how), and the rule and threshold by which cells
// divide. Both are off by default (growth.field: none, division.rule: none).
// Read into ready-to-use growth/ objects, so every error (a bad expression,
// a dome projection without a dome tissue) is a ConfigError at its key.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessella/growth/division_rule.hpp"
#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/growth/size_threshold.hpp"
#include "tessella/growth/velocity_field.hpp"
#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/sim/sections/section_unit.hpp"
#include "tessella/sim/sections/tissue_section.hpp"
#include "tessella/sim/stages/growth_stages.hpp"

namespace tessella::sim {

struct GrowthSpec {
  /// Null when growth.field is none (no growth stage).
  std::shared_ptr<const growth::VelocityField> field;
  growth::GrowthOptions options;
};

struct DivisionSpec {
  /// Null when division.rule is none (no division stage).
  std::shared_ptr<const growth::DivisionRule> rule;
  std::optional<growth::SizeThreshold> threshold;
  growth::DivisionOptions options;
  /// division.gate; none: no gate.
  std::optional<DivisionGate> gate;
};

void declareGrowthSection(Schema& schema);
void declareDivisionSection(Schema& schema);
/// `tissue` is needed for growth.surface: dome (the dome the tissue was built on).
GrowthSpec readGrowthSection(const Config& config, const TissueSpec& tissue);
DivisionSpec readDivisionSection(const Config& config);
/// The growth stage, when growth.field is not none.
void addGrowthStage(const GrowthSpec& growth, StageList& stages);
/// The division stage, when division.rule is not none.
void addDivisionStage(const DivisionSpec& division, StageList& stages);
/// division.gate.field must name one of the cell properties the stages write
/// (`fields`, Stage::cellPropertiesWritten); ConfigError at the key otherwise.
void checkDivisionGate(const Config& config, const DivisionSpec& division, const std::vector<std::string>& fields);

}  // namespace tessella::sim
