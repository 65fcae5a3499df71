// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_system.hpp"

using namespace tessella;
using namespace tessella::networks;

namespace {
void compareWithDifferences(NetworkSystem& system, const std::vector<double>& y) {
  CsrMatrix J;
  system.jacobian(0.0, y, J);
  const std::size_t n = system.size();
  double largest = 0.0;
  for (double v : J.value) largest = std::max(largest, std::abs(v));
  REQUIRE(largest > 0.0);
  std::vector<double> yp = y, fp(n), fm(n);
  std::size_t outside = 0;
  for (std::size_t col = 0; col < n; ++col) {
    const double h = 1e-6 * std::max(1.0, std::abs(y[col]));
    yp[col] = y[col] + h;
    system.rhs(0.0, yp, fp);
    yp[col] = y[col] - h;
    system.rhs(0.0, yp, fm);
    yp[col] = y[col];
    for (std::size_t row = 0; row < n; ++row) {
      const double fd = (fp[row] - fm[row]) / (2 * h);
      const double an = J.at(row, col);
      INFO("row " << row << " column " << col);
      CHECK(std::abs(an - fd) <= 1e-6 * largest);
      if (std::abs(fd) > 1e-9 * largest) {
        // A non-zero derivative must be inside the pattern.
        const auto first = J.column.begin() + static_cast<std::ptrdiff_t>(J.row_start[row]);
        const auto last = J.column.begin() + static_cast<std::ptrdiff_t>(J.row_start[row + 1]);
        if (!std::binary_search(first, last, col)) ++outside;
      }
    }
  }
  CHECK(outside == 0);
}
}  // namespace

TEST_CASE("The Jacobian matches central differences: reactions, passive transport, PIN", "[networks]") {
  Tissue t = hexagonalGrid(5, 4, 1.0);
  GeometryCache geometry;
  NetworkModel m;
  m.species = {{"a", "p - d * a + a * b / (1 + a^2)", 0.3}, {"b", "a^2 - b", 0.1}};
  m.parameters = {{"p", 1.0}, {"d", 0.5}};
  m.pin.species = "a";
  m.pin.rate = 1.5;
  m.pin.saturation = 0.2;
  SECTION("exponential") { m.pin.function = PinFunction::Exponential; }
  SECTION("power") {
    m.pin.function = PinFunction::Power;
    m.pin.exponent = 2.0;
  }
  NetworkSystem system(m, networkGraph(t, geometry, {}));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.2, 2.0);
  std::vector<double> y(system.size());
  for (double& v : y) v = u(rng);
  compareWithDifferences(system, y);
}
