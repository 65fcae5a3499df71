// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/pin_model.hpp"

#include <algorithm>
#include <cmath>

namespace tessella::networks {

const EnumTable<PinModel>& pinModels() {
  static const EnumTable<PinModel> table(
      "PIN model", {{"up_the_gradient", PinModel::UpTheGradient,
                     "PIN toward neighbour j grows with f(c_j) (Joensson et al. 2006, Smith et al. 2006)."}});
  return table;
}

const EnumTable<PinFunction>& pinFunctions() {
  static const EnumTable<PinFunction> table(
      "PIN weight function", {{"exponential", PinFunction::Exponential, "f(c) = base^c (Smith et al. 2006)."},
                              {"power", PinFunction::Power, "f(c) = c^exponent (Joensson et al. 2006: exponent 1)."}});
  return table;
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

}  // namespace tessella::networks
