// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One mechanics step of a planar tissue (docs/mechanics.md): walls without a
// rest length get their current one, the wall-spring/turgor equilibrium is
// solved (positions move there), the walls' strain and tension and the cells'
// pressures are written as properties, then rest lengths grow by the
// Lockhart-Ortega law over dt.

#include "tessella/mechanics/boundary_conditions.hpp"
#include "tessella/mechanics/equilibrium.hpp"
#include "tessella/mechanics/strain_growth.hpp"

namespace tessella {
class Tissue;
}

namespace tessella::mechanics {

struct TurgorGrowthParams {
  double youngs_modulus = 1.0;  ///< E of every wall
  double thickness = 1.0;       ///< t of every wall: the stiffness is S = E t
  /// Pressure of cells that have none yet (the turgor_pressure column's
  /// default); a model may set each cell's turgor_pressure between steps.
  double pressure = 0.1;
  StrainGrowthLaw growth{};
  Supports supports{};
  EquilibriumOptions solver{};

  /// Throws InputError naming the parameter and value when out of range.
  void check() const;
};

struct TurgorStepReport {
  EquilibriumReport equilibrium;
  std::size_t walls_initialised = 0;  ///< walls given their current length as rest length
  double max_strain = 0.0;
  double mean_growth_rate = 0.0;      ///< mean (1/L0) dL0/dt over the walls
};

/// Prepares the state columns (rest_length, wall_strain, wall_tension,
/// growth_rate, turgor_pressure) without changing positions.
void prepareTurgorState(Tissue& tissue, const TurgorGrowthParams& params);

/// One step of length dt (dt = 0: equilibrium only). On an EquilibriumError
/// the tissue is unchanged. Each wall's growth_rate is (L0' - L0) / (L0 dt)
/// of this step's growth (0 when dt = 0).
TurgorStepReport turgorGrowthStep(Tissue& tissue, const TurgorGrowthParams& params, double dt);

}  // namespace tessella::mechanics
