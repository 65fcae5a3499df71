// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// drawPositiveNormals: many draws of N(mean, stddev), each redrawn until
// positive, the same values (bit for bit) and the same engine state after as
// drawing them one after the other from one std::normal_distribution:
//
//   std::normal_distribution<double> draw(mean, stddev);
//   for (double& v : out) do v = draw(rng); while (!(v > 0));
//
// The engine is drawn serially (it is one stream); the logarithms and square
// roots of the polar method, most of the cost, run in parallel (OpenMP).
// With libstdc++ (whose std::normal_distribution is the polar method written
// out here); with another standard library the loop above runs as it is.

#include <span>

#include "tessella/growth/division_rule.hpp"  // Rng

namespace tessella::growth {

void drawPositiveNormals(Rng& rng, double mean, double stddev, std::span<double> out);

}  // namespace tessella::growth
