// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// PIN allocation: how a cell distributes its efflux carriers over the walls it
// shares with its neighbours (docs/networks.md, "Equations").
//
// `up_the_gradient` (Joensson et al. 2006 PNAS, Smith et al. 2006 PNAS), algebraic:
// the PIN on cell i's side of the wall to neighbour j is
//   PIN_ij = P_i L_ij f(c_j) / (kappa + sum_k L_ik f(c_k)),   k over i's neighbours,
// with f(c) = b^c (exponential) or c^n (power), and the efflux of the transported
// species from i into j is T PIN_ij g(c_i) (amount per unit time), with the cell's PIN
// P_i = total + total_per_concentration c_i (Smith et al.: PIN made in proportion to
// auxin, at its steady state) and g(c) = c (efflux `linear`) or c^2 / (1 + s c^2)
// (efflux `saturating`, Smith et al.).
//
// `with_the_flux` (canalization: Mitchison 1980; Rolland-Lagan & Prusinkiewicz 2005;
// Feugier et al. 2005; Bayer et al. 2009) and `expression`: PIN is a state, a
// density p_ij (per unit wall measure) on each side of each interface, with
//   dp_ij/dt = (basal + production h(phi_ij)) B_i - decay p_ij          (with_the_flux)
//   dp_ij/dt = the user's expression                                     (expression)
// h(phi) = max(phi, 0)^m / (1 + s max(phi, 0)^m), phi_ij the net flux density of
// the species from i into j, B_i = 1 - sum_k L_ik p_ik / P_i when bounded (else 1);
// the efflux from i into j is T L_ij p_ij c_i.

#include <string>
#include <vector>

#include "tessella/tissue/enum_table.hpp"

namespace tessella::networks {

enum class PinModel { UpTheGradient, WithTheFlux, Expression };
enum class PinFunction { Exponential, Power };
enum class PinEfflux { Linear, Saturating };

/// "up_the_gradient", "with_the_flux", "expression".
const EnumTable<PinModel>& pinModels();
/// "exponential" (f = base^c), "power" (f = c^exponent).
const EnumTable<PinFunction>& pinFunctions();
/// up_the_gradient's efflux g(c_i): "linear" (c), "saturating" (c^2 / (1 + efflux_saturation c^2)).
const EnumTable<PinEfflux>& pinEffluxes();

/// The variables of a PIN expression besides the parameters and t:
/// c_i, c_j, pin, pin_opposite, flux, wall, measure, pin_cell.
const std::vector<std::string>& pinExpressionVariables();

struct PinTransport {
  std::string species;  ///< the transported species; empty: no PIN transport
  PinModel model = PinModel::UpTheGradient;
  PinFunction function = PinFunction::Exponential;
  double base = 3.0;      ///< b of f = b^c (> 1 for up-the-gradient polarity)
  double exponent = 1.0;  ///< n of f = c^n (> 0)
  double rate = 1.0;      ///< T: efflux per unit PIN and unit concentration (>= 0)
  double total =
      1.0;  ///< P_i: PIN per cell (>= 0); with_the_flux: the bound of a cell's PIN when `bounded`
  double saturation = 0.0;  ///< kappa >= 0, in units of wall measure (up_the_gradient)

  // --- PIN as a state (with_the_flux, expression) ---
  double basal = 0.0;            ///< rho_0 >= 0: production of PIN density without flux
  double production = 1.0;       ///< rho >= 0: production per unit h(phi)
  double decay = 1.0;            ///< mu >= 0: PIN density decays at mu p
  double flux_exponent = 2.0;    ///< m >= 1 of h(phi) = phi^m / (1 + s phi^m)
  double flux_saturation = 0.0;  ///< s >= 0 (0: no saturation)
  /// Production times B_i = 1 - (PIN amount on cell i's interfaces) / total: a cell's PIN stays
  /// below total.
  bool bounded = false;
  double initial = 0.0;  ///< PIN density on every wall side at the start and on new walls (>= 0)
  std::string
      expression;  ///< `expression`: dp_ij/dt over pinExpressionVariables() and the parameters

  // --- up_the_gradient after Smith et al. 2006 (last, so aggregate initialisers of the above stay valid) ---
  PinEfflux efflux = PinEfflux::Linear;  ///< g(c_i) of the efflux T PIN_ij g(c_i)
  double efflux_saturation = 0.0;        ///< s >= 0 of g(c) = c^2 / (1 + s c^2) (saturating)
  /// P_i = total + total_per_concentration c_i (>= 0): PIN made in proportion to the transported species.
  double total_per_concentration = 0.0;

  bool enabled() const { return !species.empty(); }
  /// PIN is a state of the ODE system (with_the_flux, expression).
  bool dynamic() const { return enabled() && model != PinModel::UpTheGradient; }
  /// f(c) and f'(c).
  double weight(double c) const;
  double weightDerivative(double c) const;
  /// up_the_gradient: G(c) = T P(c) g(c), so that J_ij = G(c_i) L_ij f(c_j) / D_i, and G'(c).
  double effluxFactor(double c) const;
  double effluxFactorDerivative(double c) const;
  /// P(c) = total + total_per_concentration c, a cell's PIN at concentration c (up_the_gradient).
  double cellPin(double c) const { return total + total_per_concentration * c; }
  /// h(phi) and h'(phi) of with_the_flux (0 for phi <= 0).
  double fluxResponse(double phi) const;
  double fluxResponseDerivative(double phi) const;
};

}  // namespace tessella::networks
