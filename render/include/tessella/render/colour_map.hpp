// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The colour map of every picture: viridis (perceptually uniform, readable
// in grey and by colour-blind readers), as matplotlib defines it.

#include <array>

namespace tessella::render {

/// Red, green, blue in [0, 1].
using Rgb = std::array<double, 3>;

/// The colour of t in [0, 1] (clamped; NaN gives grey).
Rgb viridis(double t);

}  // namespace tessella::render
