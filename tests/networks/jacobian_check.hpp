// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The Jacobian of a NetworkSystem against central differences of its
// right-hand side: every entry to 1e-6 of the largest, and every derivative
// that is not zero inside the pattern.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tessella/networks/network_system.hpp"

namespace tessella::networks::testing {

inline void compareWithDifferences(NetworkSystem& system, const std::vector<double>& y) {
  CsrMatrix J;
  system.jacobian(0.0, y, J);
  const std::size_t n = system.size();
  double largest = 0.0;
  for (double v : J.value) largest = std::max(largest, std::abs(v));
  REQUIRE(largest > 0.0);
  std::vector<double> yp = y, fp(n), fm(n);
  std::size_t outside = 0, compared = 0;
  for (std::size_t col = 0; col < n; ++col) {
    const double h = 1e-6 * std::max(1.0, std::abs(y[col]));
    yp[col] = y[col] + h;
    system.rhs(0.0, yp, fp);
    yp[col] = y[col] - h;
    system.rhs(0.0, yp, fm);
    yp[col] = y[col];
    for (std::size_t row = 0; row < n; ++row) {
      const double fd = (fp[row] - fm[row]) / (2 * h);
      INFO("row " << row << " column " << col << " (amounts end at " << system.numSpecies() * system.numCells()
                  << ")");
      CHECK(std::abs(J.at(row, col) - fd) <= 1e-6 * largest);
      if (std::abs(fd) > 1e-9 * largest) {
        ++compared;
        const auto first = J.column.begin() + static_cast<std::ptrdiff_t>(J.row_start[row]);
        const auto last = J.column.begin() + static_cast<std::ptrdiff_t>(J.row_start[row + 1]);
        if (!std::binary_search(first, last, col)) ++outside;
      }
    }
  }
  CHECK(compared > n);
  CHECK(outside == 0);
}

}  // namespace tessella::networks::testing
