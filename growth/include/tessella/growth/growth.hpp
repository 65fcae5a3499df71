// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Everything in growth/: velocity fields, the integrator, harmonic
// interpolation, division rules, thresholds, the scheduler and the tables
// that name them (registries.hpp).

#include "tessella/growth/besson_dumais_rule.hpp"
#include "tessella/growth/bump_field.hpp"
#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/division_walls.hpp"
#include "tessella/growth/expression_field.hpp"
#include "tessella/growth/fixed_direction_rule.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/growth/harmonic_interpolation.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/growth/main_axis_rule.hpp"
#include "tessella/growth/meristem_field.hpp"
#include "tessella/growth/perpendicular_wall_rule.hpp"
#include "tessella/growth/radial_field.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/growth/random_direction_rule.hpp"
#include "tessella/growth/shortest_wall_rule.hpp"
#include "tessella/growth/size_threshold.hpp"
#include "tessella/growth/surface_projection.hpp"
