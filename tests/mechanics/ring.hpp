// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A regular N-gon of wall springs (one cell) and its closed forms
// (docs/mechanics.md, "The ring"): with stiffness S = E t, rest length L0 and
// pressure P, the equilibrium side is L = L0 / (1 - a), a = P L0 / (2 S tan(pi/N)).

#include "tessella/tissue/tissue.hpp"

namespace tessella::test {

/// One cell: a regular N-gon of side `side` centred at the origin, vertex 0 on +x.
Tissue ringTissue(int n, double side);
/// a = P L0 / (2 S tan(pi / N)).
double ringLoad(int n, double pressure, double stiffness, double rest_length);
/// Equilibrium side L0 / (1 - a) (requires a < 1).
double ringSide(int n, double pressure, double stiffness, double rest_length);

}  // namespace tessella::test
