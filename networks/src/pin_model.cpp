// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/pin_model.hpp"

#include <algorithm>
#include <cmath>

namespace tessella::networks {

const EnumTable<PinModel>& pinModels() {
  static const EnumTable<PinModel> table(
      "PIN model",
      {{"up_the_gradient", PinModel::UpTheGradient,
        "PIN toward neighbour j grows with f(c_j) (Joensson et al. 2006, Smith et al. 2006); no PIN state."},
       {"with_the_flux", PinModel::WithTheFlux,
        "PIN density on each wall side is a state produced with the net flux through the wall (canalization: "
        "Mitchison 1980, Rolland-Lagan & Prusinkiewicz 2005, Bayer et al. 2009) and decaying."},
       {"expression", PinModel::Expression,
        "PIN density on each wall side is a state whose rate of change is a muparser expression "
        "(pin.expression)."}});
  return table;
}

const EnumTable<PinFunction>& pinFunctions() {
  static const EnumTable<PinFunction> table(
      "PIN weight function", {{"exponential", PinFunction::Exponential, "f(c) = base^c (Smith et al. 2006)."},
                              {"power", PinFunction::Power, "f(c) = c^exponent (Joensson et al. 2006: exponent 1)."}});
  return table;
}

const EnumTable<PinEfflux>& pinEffluxes() {
  static const EnumTable<PinEfflux> table(
      "PIN efflux",
      {{"linear", PinEfflux::Linear,
        "g(c_i) = c_i: efflux in proportion to the cell's concentration (Joensson et al. 2006)."},
       {"saturating", PinEfflux::Saturating,
        "g(c_i) = c_i^2 / (1 + efflux_saturation c_i^2): quadratic, saturating efflux (Smith et al. 2006)."}});
  return table;
}

const std::vector<std::string>& pinExpressionVariables() {
  static const std::vector<std::string> names = {"c_i",  "c_j",  "pin",     "pin_opposite",
                                                 "flux", "wall", "measure", "pin_cell"};
  return names;
}

double PinTransport::weight(double c) const {
  if (function == PinFunction::Exponential) return std::pow(base, c);
  return std::pow(std::max(c, 0.0), exponent);
}

double PinTransport::weightDerivative(double c) const {
  if (function == PinFunction::Exponential) return std::log(base) * std::pow(base, c);
  if (c <= 0.0) return exponent == 1.0 ? 1.0 : 0.0;
  return exponent * std::pow(c, exponent - 1.0);
}

double PinTransport::effluxFactor(double c) const {
  if (efflux == PinEfflux::Linear) return rate * cellPin(c) * c;
  const double c2 = c * c;
  return rate * cellPin(c) * c2 / (1.0 + efflux_saturation * c2);
}

double PinTransport::effluxFactorDerivative(double c) const {
  if (efflux == PinEfflux::Linear) return rate * (total_per_concentration * c + cellPin(c));
  // g = c^2 / d, d = 1 + s c^2: g' = 2 c / d^2.
  const double c2 = c * c, d = 1.0 + efflux_saturation * c2;
  return rate * (total_per_concentration * c2 / d + cellPin(c) * 2.0 * c / (d * d));
}

double PinTransport::fluxResponse(double phi) const {
  if (!(phi > 0.0)) return 0.0;
  const double q = std::pow(phi, flux_exponent);
  return q / (1.0 + flux_saturation * q);
}

double PinTransport::fluxResponseDerivative(double phi) const {
  if (!(phi > 0.0)) return 0.0;
  const double q = std::pow(phi, flux_exponent);
  const double d = 1.0 + flux_saturation * q;
  return flux_exponent * std::pow(phi, flux_exponent - 1.0) / (d * d);
}

}  // namespace tessella::networks
