// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The walls' mechanical state as tissue properties, so that it divides with
// the tissue and reaches the VTU output:
//   rest_length   (wall, SplitByMeasure, default 0): a split wall's two parts
//                 carry its rest length in proportion to their lengths; a new
//                 wall (division) gets 0, which means "at rest at its current
//                 length" and is set by initialiseRestLengths() before the
//                 next equilibrium;
//   wall_strain, wall_tension (wall, Copy): outputs of the last equilibrium;
//   turgor_pressure (cell, Copy): the pressure each cell was solved with;
//   extensibility (cell, Copy; optional): phi of the growth law per cell. When
//                 the tissue has it, a wall grows with the mean of its cells'
//                 values (a sheet's membrane: its cell's) instead of the law's
//                 extensibility, so a model may set it per cell between steps.

#include <cstddef>
#include <vector>

#include "tessella/tissue/properties.hpp"

namespace tessella {
class Tissue;
}

namespace tessella::mechanics {

inline constexpr const char* kRestLengthName = "rest_length";
inline constexpr const char* kWallStrainName = "wall_strain";
inline constexpr const char* kWallTensionName = "wall_tension";
inline constexpr const char* kTurgorPressureName = "turgor_pressure";
inline constexpr const char* kExtensibilityName = "extensibility";

/// Per wall slot, phi of the growth law: the mean of the wall's cells'
/// `extensibility` when the tissue has that cell property, else `fallback`
/// (the law's). InputError naming the cell for a negative or non-finite value.
std::vector<double> wallExtensibilities(const Tissue& tissue, double fallback);

/// The rest-length column of the walls, added (all 0) if missing.
PropertyColumn<double>& restLengths(Tissue& tissue);
/// A double wall column `name` with policy Copy, added (default 0) if missing.
PropertyColumn<double>& wallOutput(Tissue& tissue, const char* name);
/// A double cell column `name` with policy Copy, added (default `value`) if missing.
PropertyColumn<double>& cellOutput(Tissue& tissue, const char* name, double value = 0.0);

/// Gives every live wall whose rest length is not > 0 its current length
/// (at rest); returns how many it set.
std::size_t initialiseRestLengths(Tissue& tissue);

}  // namespace tessella::mechanics
