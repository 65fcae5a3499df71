// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// NetworkModel: a cell-level regulatory network as plain data (no YAML): the
// species every cell carries, named parameters, one reaction rate per species
// (a muparser expression), passive exchange across walls and PIN-mediated
// efflux. The equations are in docs/networks.md.

#include <map>
#include <string>
#include <vector>

#include "tessella/networks/pin_model.hpp"

namespace tessella::networks {

struct NetworkSpecies {
  std::string name;  ///< letters, digits, '_'; a variable of the reactions (the cell's concentration)
  /// Rate of change of the concentration by reactions inside the cell (per unit time), a muparser
  /// expression over the cell's species, the parameters, `measure` (cell area / volume), x, y, z
  /// (its centroid) and the named cell properties. Empty: no reaction.
  std::string reaction;
  /// Passive permeability P (>= 0): a wall of measure L between cells i and j moves
  /// P L (c_i - c_j) of the amount per unit time from i to j.
  double permeability = 0.0;
};

struct NetworkModel {
  std::vector<NetworkSpecies> species;
  std::map<std::string, double> parameters;
  /// Cell properties (double or int) the reactions read (constant during an integration).
  std::vector<std::string> cell_properties;
  /// Carrier-mediated efflux of one species; off when pin.species is empty.
  PinTransport pin;

  /// Index of a species, or -1.
  int speciesIndex(const std::string& name) const;
  /// Throws InputError naming the species / parameter / name at fault: names
  /// that are empty, not plain, repeated or reserved, negative permeabilities,
  /// a PIN species that is not a species, non-finite parameters.
  void validate() const;
};

/// Names a reaction may use besides species, parameters and properties.
const std::vector<std::string>& reservedNetworkNames();

}  // namespace tessella::networks
