// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The tables of growth/: every division rule, division threshold, velocity
// field and surface that a configuration or a script picks by name, each with
// a doc string, the parameters it reads (name, type, default, range:
// tessella/tissue/parameters.hpp) and its factory. sim/ declares its YAML
// keys and reads them from these tables, the Python bindings list and build
// from them, and docs/config.md is generated from them. The integrator's
// enums have their name tables beside them (growth_integrator.hpp:
// integrationSchemes(), velocitySources()).
//
// Extension point: a new division rule (velocity field, ...) is its source
// file, which defines the class and an entry function returning the table
// entry (e.g. `DivisionRuleEntry mainAxisRuleEntry()` in main_axis_rule.cpp),
// and one line in the concept's table source (growth/src/division_rule_table.cpp,
// velocity_field_table.cpp, division_threshold_table.cpp, surface_table.cpp).
// No header is needed. A factory's InputError about one parameter is a
// ParamError naming it, so readers can point at its key. See docs/extending.md.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tessella/growth/division_rule.hpp"
#include "tessella/growth/size_threshold.hpp"
#include "tessella/growth/surface_projection.hpp"
#include "tessella/growth/velocity_field.hpp"
#include "tessella/tissue/registry.hpp"

namespace tessella::growth {

using DivisionRuleFactory = std::function<std::shared_ptr<const DivisionRule>(const ParamValues&)>;
using DivisionRuleEntry = RegistryEntry<DivisionRuleFactory>;
/// main_axis, shortest_wall, perpendicular_to_mother_wall, random, fixed, besson_dumais, ...
const Registry<DivisionRuleFactory>& divisionRules();

using DivisionThresholdFactory = std::function<SizeThreshold(const ParamValues&)>;
using DivisionThresholdEntry = RegistryEntry<DivisionThresholdFactory>;
/// fixed, property, noisy (SizeThreshold).
const Registry<DivisionThresholdFactory>& divisionThresholds();

using VelocityFieldFactory = std::function<std::shared_ptr<const VelocityField>(const ParamValues&)>;
using VelocityFieldEntry = RegistryEntry<VelocityFieldFactory>;
/// uniform, anisotropic, radial, bump, meristem, expression.
const Registry<VelocityFieldFactory>& velocityFields();

/// `tissue_surface` is the projection onto the surface the tissue was built
/// on (its dome), or empty when it was built on none.
using SurfaceFactory = std::function<SurfaceProjection(const ParamValues&, const SurfaceProjection& tissue_surface)>;
using SurfaceEntry = RegistryEntry<SurfaceFactory>;
/// sphere, paraboloid, dome.
const Registry<SurfaceFactory>& surfaces();

/// The rule named `name` (divisionRules().make): InputError naming the value
/// and listing the known names for an unknown rule, naming the parameter for
/// a parameter the rule does not read or a value out of its range.
std::shared_ptr<const DivisionRule> makeDivisionRule(const std::string& name, const ParamValues& params = {});
/// The rule names in table order.
std::vector<std::string> divisionRuleNames();

}  // namespace tessella::growth
