// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace tessella {

namespace {

// to_chars writes "-nan" for a NaN with its sign bit set (0/0 on x86); a NaN has no sign to a reader.
constexpr const char* kNaN = "nan";

template <typename Format>
std::string pointText(const Vec3& p, Format format) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) about "(" + std::string&&.
  std::string text = "(";
  for (int i = 0; i < 3; ++i) {
    if (i > 0) text += ", ";
    text += format(p[i]);
  }
  text += ")";
  return text;
}

}  // namespace

std::string formatNumber(double x) {
  if (std::isnan(x)) return kNaN;
  char buffer[32];  // the longest shortest form, "-2.2250738585072014e-308", has 24 characters
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string formatNumber(double x, int significant_digits) {
  if (std::isnan(x)) return kNaN;
  // 17 significant digits already read back exactly; more would only add noise and length.
  const int digits = std::clamp(significant_digits, 1, 17);
  char buffer[32];  // sign, 17 digits, point, "e-308": 25 characters at most
  const std::to_chars_result result =
      std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, digits);
  return std::string(buffer, result.ptr);
}

std::string formatPoint(const Vec3& p) {
  return pointText(p, [](double x) { return formatNumber(x); });
}

std::string formatPoint(const Vec3& p, int significant_digits) {
  return pointText(p, [significant_digits](double x) { return formatNumber(x, significant_digits); });
}

}  // namespace tessella
