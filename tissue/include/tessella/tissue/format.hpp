// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Numbers as text: the one spelling of a double in the messages, reports and
// text files Tessella writes (docs/ARCHITECTURE.md, "Conventions").
//
// formatNumber(x) is exact: the shortest text that reads back to the same
// double. Use it for a value someone gave (an option, a key, a file's value)
// and for anything that must read back (file contents, run state).
// formatNumber(x, digits) rounds to `digits` significant digits, as printf's
// %.<digits>g does. Use it for a computed quantity whose later digits say
// nothing to a reader (an estimate, a measure, a distance in a diagnosis).

#include <string>

#include "tessella/tissue/vec3.hpp"

namespace tessella {

/// "0.1", "2", "-3.5", "1e-12", "1e+20", "inf", "-inf"; a NaN is "nan"
/// whatever its sign bit.
std::string formatNumber(double x);

/// Rounded to `significant_digits` (>= 1), trailing zeros dropped:
/// formatNumber(2.0 / 3.0, 6) is "0.666667", formatNumber(2.5e13, 3) "2.5e+13".
std::string formatNumber(double x, int significant_digits);

/// "(x, y, z)", each coordinate as formatNumber(x) writes it.
std::string formatPoint(const Vec3& p);

/// "(x, y, z)", each coordinate as formatNumber(x, significant_digits) writes it.
std::string formatPoint(const Vec3& p, int significant_digits);

}  // namespace tessella
