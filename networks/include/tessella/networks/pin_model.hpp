// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// PIN allocation: how a cell distributes its efflux carriers over the walls it
// shares with its neighbours. `up_the_gradient` (Joensson et al. 2006 PNAS,
// Smith et al. 2006 PNAS): the PIN on cell i's side of the wall to neighbour j is
//   PIN_ij = P_i L_ij f(c_j) / (kappa + sum_k L_ik f(c_k)),   k over i's neighbours,
// with f(c) = b^c (exponential) or c^n (power), and the efflux of the transported
// species from i into j is T PIN_ij c_i (amount per unit time).

#include <string>

#include "tessella/tissue/enum_table.hpp"

namespace tessella::networks {

enum class PinModel { UpTheGradient };
enum class PinFunction { Exponential, Power };

/// "up_the_gradient".
const EnumTable<PinModel>& pinModels();
/// "exponential" (f = base^c), "power" (f = c^exponent).
const EnumTable<PinFunction>& pinFunctions();

struct PinTransport {
  std::string species;  ///< the transported species; empty: no PIN transport
  PinModel model = PinModel::UpTheGradient;
  PinFunction function = PinFunction::Exponential;
  double base = 3.0;       ///< b of f = b^c (> 1 for up-the-gradient polarity)
  double exponent = 1.0;   ///< n of f = c^n (> 0)
  double rate = 1.0;       ///< T: efflux per unit PIN and unit concentration (>= 0)
  double total = 1.0;      ///< P_i: PIN per cell (>= 0)
  double saturation = 0.0; ///< kappa >= 0, in units of wall measure

  bool enabled() const { return !species.empty(); }
  /// f(c) and f'(c).
  double weight(double c) const;
  double weightDerivative(double c) const;
};

}  // namespace tessella::networks
