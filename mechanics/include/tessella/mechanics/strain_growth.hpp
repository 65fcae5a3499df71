// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Lockhart-Ortega strain-based growth of a wall's rest length (docs/mechanics.md):
//   dL0/dt = extensibility * L0 * max(strain - threshold, 0),  strain = (L - L0) / L0.
// Integrated over a step with the strain of the step's equilibrium held fixed:
// L0 <- L0 exp(extensibility * max(strain - threshold, 0) * dt), exact for a
// constant strain and first order in dt otherwise (never shrinks, never
// crosses zero).

namespace tessella::mechanics {

struct StrainGrowthLaw {
  double extensibility = 0.0;  ///< phi >= 0, per unit time and unit strain
  double threshold = 0.0;      ///< yield strain epsilon_y >= 0

  /// Throws InputError naming the parameter and its value when out of range.
  void check() const;
  /// (1/L0) dL0/dt at `strain`.
  double relativeRate(double strain) const;
  /// The rest length after a step dt at constant `strain`.
  double grownRestLength(double rest_length, double strain, double dt) const;
};

}  // namespace tessella::mechanics
