// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/network_model.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::networks {

namespace {
bool plainName(const std::string& s) {
  return !s.empty() && !std::isdigit(static_cast<unsigned char>(s[0])) &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}
}  // namespace

const std::vector<std::string>& reservedNetworkNames() {
  static const std::vector<std::string> names = {"measure", "x", "y", "z", "t"};
  return names;
}

int NetworkModel::speciesIndex(const std::string& name) const {
  for (std::size_t s = 0; s < species.size(); ++s)
    if (species[s].name == name) return static_cast<int>(s);
  return -1;
}

void NetworkModel::validate() const {
  if (species.empty()) throw InputError("network: no species");
  std::set<std::string> seen;
  const auto& reserved = reservedNetworkNames();
  auto claim = [&](const std::string& name, const std::string& what) {
    if (!plainName(name))
      throw InputError("network: " + what + " '" + name +
                       "' is not a name (letters, digits and '_', not starting with a digit)");
    if (std::find(reserved.begin(), reserved.end(), name) != reserved.end())
      throw InputError("network: " + what + " '" + name + "' is a reserved name (measure, x, y, z, t)");
    if (!seen.insert(name).second) throw InputError("network: " + what + " '" + name + "' is named twice");
  };
  for (const NetworkSpecies& s : species) {
    claim(s.name, "species");
    if (!(std::isfinite(s.permeability) && s.permeability >= 0.0))
      throw InputError("network: species '" + s.name + "': permeability " + std::to_string(s.permeability) +
                       " must be finite and >= 0");
  }
  // The neighbourhood terms of the reactions are names too.
  for (const NetworkSpecies& s : species) {
    for (const char* prefix : {"sum_", "mean_"}) {
      const std::string name = prefix + s.name;
      if (!seen.insert(name).second)
        throw InputError("network: '" + name + "' names both a species and the neighbourhood term " + prefix +
                         "<" + s.name + ">");
    }
  }
  for (const auto& [name, value] : parameters) {
    claim(name, "parameter");
    if (!std::isfinite(value)) throw InputError("network: parameter '" + name + "' is not finite");
  }
  for (const std::string& p : cell_properties) claim(p, "cell property");
  if (pin.enabled()) {
    if (speciesIndex(pin.species) < 0)
      throw InputError("network: PIN transport of '" + pin.species + "', which is not a species");
    auto nonneg = [&](double v, const char* what) {
      if (!(std::isfinite(v) && v >= 0.0))
        throw InputError(std::string("network: PIN ") + what + " " + std::to_string(v) + " must be finite and >= 0");
    };
    nonneg(pin.rate, "rate");
    nonneg(pin.total, "total");
    nonneg(pin.saturation, "saturation");
    nonneg(pin.efflux_saturation, "efflux_saturation");
    nonneg(pin.total_per_concentration, "total_per_concentration");
    if (pin.function == PinFunction::Exponential && !(std::isfinite(pin.base) && pin.base > 0.0))
      throw InputError("network: PIN base " + std::to_string(pin.base) + " must be > 0");
    if (pin.function == PinFunction::Power && !(std::isfinite(pin.exponent) && pin.exponent > 0.0))
      throw InputError("network: PIN exponent " + std::to_string(pin.exponent) + " must be > 0");
    if (pin.dynamic()) {
      auto atLeast = [&](double v, double low, const char* what) {
        if (!(std::isfinite(v) && v >= low))
          throw InputError(std::string("network: PIN ") + what + " " + formatNumber(v) + " must be finite and >= " +
                           formatNumber(low));
      };
      atLeast(pin.basal, 0.0, "basal");
      atLeast(pin.production, 0.0, "production");
      atLeast(pin.decay, 0.0, "decay");
      atLeast(pin.flux_exponent, 1.0, "flux_exponent");
      atLeast(pin.flux_saturation, 0.0, "flux_saturation");
      atLeast(pin.initial, 0.0, "initial");
      if (pin.bounded && !(pin.total > 0.0))
        throw InputError("network: bounded PIN needs total > 0 (total " + formatNumber(pin.total) + ")");
      if (pin.model == PinModel::Expression) {
        if (pin.expression.find_first_not_of(" \t") == std::string::npos)
          throw InputError("network: the PIN model 'expression' needs pin.expression (dPIN_ij/dt)");
        const auto& vars = pinExpressionVariables();
        for (const auto& [name, value] : parameters)
          if (std::find(vars.begin(), vars.end(), name) != vars.end())
            throw InputError("network: parameter '" + name + "' is a variable of the PIN expression (c_i, c_j, "
                             "pin, pin_opposite, flux, wall, measure, pin_cell)");
      }
    }
  }
}

}  // namespace tessella::networks
