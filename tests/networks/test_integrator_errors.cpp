// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include "network_fixtures.hpp"
#include "tessella/networks/network_integrator.hpp"

using namespace tessella;
using namespace tessella::networks;

TEST_CASE("A CVODE failure names the time, the flag, the species and the cell", "[networks]") {
  // Only b in cell 2 changes (fast): it carries the largest local error.
  NetworkModel m;
  m.species = {{"a", "", 0.0}, {"b", "x > 1.5 ? 50 * cos(50 * t) : 0", 0.0}};
  NetworkSystem system(m, testing::chainGraph({1.0, 1.0, 1.0}, {1.0, 1.0}));
  IntegratorOptions o;
  o.max_steps = 5;
  NetworkIntegrator integrator(system, o);
  std::vector<double> y{1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  try {
    integrator.advance(y, 0.0, 10.0);
    FAIL("expected a NetworkIntegrationError");
  } catch (const NetworkIntegrationError& e) {
    CHECK(e.species() == "b");
    CHECK(e.cell() == 2);
    CHECK(e.flag() == -1);  // CV_TOO_MUCH_WORK
    CHECK(e.time() > 0.0);
    CHECK(e.time() < 10.0);
    CHECK_THAT(e.what(), Catch::Contains("CV_TOO_MUCH_WORK") && Catch::Contains("species 'b' of cell 2"));
  }
}

TEST_CASE("Bad integrator options are refused by name", "[networks]") {
  NetworkSystem system(testing::oneSpecies("a", 1.0), testing::chainGraph({1.0, 1.0}, {1.0}));
  IntegratorOptions o;
  o.relative_tolerance = 0.0;
  REQUIRE_THROWS_WITH(NetworkIntegrator(system, o), Catch::Contains("relative_tolerance"));
}
