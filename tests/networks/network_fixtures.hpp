// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Small graphs and models shared by the networks tests.

#include <vector>

#include "tessella/networks/network_graph.hpp"
#include "tessella/networks/network_model.hpp"

namespace tessella::networks::testing {

/// A path of n cells with the given measures; interface k joins k and k+1
/// with measure wall[k].
inline NetworkGraph chainGraph(const std::vector<double>& measure, const std::vector<double>& wall) {
  NetworkGraph g;
  g.measure = measure;
  for (std::size_t c = 0; c < measure.size(); ++c) g.centroid.push_back(Vec3(static_cast<double>(c), 0, 0));
  for (std::size_t k = 0; k + 1 < measure.size(); ++k)
    g.interfaces.push_back({static_cast<int>(k), static_cast<int>(k + 1), wall[k], Vec3(1, 0, 0)});
  return g;
}

inline NetworkModel oneSpecies(const std::string& name, double permeability, const std::string& reaction = "") {
  NetworkModel m;
  m.species.push_back({name, reaction, permeability});
  return m;
}

}  // namespace tessella::networks::testing
