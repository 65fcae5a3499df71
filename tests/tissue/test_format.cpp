// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// formatNumber / formatPoint: the one spelling of a double in messages and text files.
#include <catch2/catch.hpp>

#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "tessella/tissue/format.hpp"

using namespace tessella;

namespace {
double readBack(const std::string& text) {
  double x = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), x);
  REQUIRE(result.ec == std::errc());
  REQUIRE(result.ptr == text.data() + text.size());
  return x;
}
}  // namespace

TEST_CASE("formatNumber writes the shortest text that reads back exactly", "[format]") {
  CHECK(formatNumber(0.1) == "0.1");
  CHECK(formatNumber(2.0) == "2");
  CHECK(formatNumber(-3.5) == "-3.5");
  CHECK(formatNumber(1e-12) == "1e-12");
  CHECK(formatNumber(2e7) == "2e+07");
  CHECK(formatNumber(1000.0) == "1000");
  CHECK(formatNumber(0.1 + 0.2) == "0.30000000000000004");
  for (double x : {1.0 / 3.0, std::sqrt(2.0), 6.02214076e23, -1.602176634e-19, std::numeric_limits<double>::min(),
                   std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min()})
    CHECK(readBack(formatNumber(x)) == x);
}

TEST_CASE("formatNumber spells infinities and NaN without a sign on NaN", "[format]") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(formatNumber(inf) == "inf");
  CHECK(formatNumber(-inf) == "-inf");
  CHECK(formatNumber(std::numeric_limits<double>::quiet_NaN()) == "nan");
  CHECK(formatNumber(-std::numeric_limits<double>::quiet_NaN()) == "nan");
  CHECK(formatNumber(-std::numeric_limits<double>::quiet_NaN(), 6) == "nan");
}

TEST_CASE("formatNumber with significant digits rounds as printf's %g does", "[format]") {
  CHECK(formatNumber(2.0 / 3.0, 6) == "0.666667");
  CHECK(formatNumber(27712812921102.04, 6) == "2.77128e+13");
  CHECK(formatNumber(12.0, 6) == "12");
  CHECK(formatNumber(1.23456789e-13, 3) == "1.23e-13");
  CHECK(formatNumber(0.5, 1) == "0.5");
  CHECK(formatNumber(0.26, 0) == "0.3");  // at least one digit
  CHECK(formatNumber(1.0 / 3.0, 40) == formatNumber(1.0 / 3.0, 17));  // 17 digits already read back exactly
}

TEST_CASE("formatPoint writes a parenthesised, comma-separated triple", "[format]") {
  CHECK(formatPoint(Vec3(0.1, -2, 1e-9)) == "(0.1, -2, 1e-09)");
  CHECK(formatPoint(Vec3(1.0 / 3.0, 0, std::numeric_limits<double>::infinity()), 4) == "(0.3333, 0, inf)");
}
