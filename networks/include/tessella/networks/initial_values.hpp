// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Initial concentrations of a species: an expression over the cell's
// centroid (x, y, z), its measure and the model's parameters, evaluated in
// every cell of a graph, plus optional uniform noise.

#include <map>
#include <random>
#include <string>
#include <vector>

#include "tessella/networks/network_graph.hpp"

namespace tessella::networks {

/// The value of `expression` (muparser: a constant such as "1.5", or e.g.
/// "1 + 0.1 * x") in every cell of `graph`, plus, with noise > 0, a uniform
/// draw in [0, noise) per cell from `rng` (cells in graph order). A syntax
/// error, an unknown name or a value that is not finite is an InputError
/// naming the expression (and the cell).
std::vector<double> initialConcentrations(const std::string& expression, const NetworkGraph& graph,
                                          const std::map<std::string, double>& parameters, double noise,
                                          std::mt19937_64& rng);

/// Parses `expression` with the variables initialConcentrations() offers:
/// InputError when it does not compile.
void checkInitialExpression(const std::string& expression, const std::map<std::string, double>& parameters);

}  // namespace tessella::networks
