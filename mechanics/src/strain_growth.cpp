// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/strain_growth.hpp"

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

#include <algorithm>
#include <cmath>

namespace tessella::mechanics {

void StrainGrowthLaw::check() const {
  if (!(extensibility >= 0.0 && std::isfinite(extensibility)))
    throw InputError("strain growth: extensibility " + formatNumber(extensibility) + " must be >= 0 and finite");
  if (!(threshold >= 0.0 && std::isfinite(threshold)))
    throw InputError("strain growth: threshold " + formatNumber(threshold) + " must be >= 0 and finite");
}

double StrainGrowthLaw::relativeRate(double strain) const {
  return extensibility * std::max(strain - threshold, 0.0);
}

double StrainGrowthLaw::grownRestLength(double rest_length, double strain, double dt) const {
  return rest_length * std::exp(relativeRate(strain) * dt);
}

}  // namespace tessella::mechanics
