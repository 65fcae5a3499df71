// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include "network_fixtures.hpp"
#include "tessella/networks/network_system.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using namespace tessella::networks;

TEST_CASE("NetworkModel::validate names the species, parameter or option at fault", "[networks]") {
  auto fails = [](const NetworkModel& m, const std::string& text) {
    REQUIRE_THROWS_AS(m.validate(), InputError);
    REQUIRE_THROWS_WITH(m.validate(), Catch::Contains(text));
  };
  NetworkModel m;
  fails(m, "no species");
  m.species = {{"a", "", 1.0}, {"a", "", 0.0}};
  fails(m, "'a' is named twice");
  m.species = {{"2a", "", 1.0}};
  fails(m, "'2a' is not a name");
  m.species = {{"measure", "", 1.0}};
  fails(m, "reserved");
  m.species = {{"a", "", -1.0}};
  fails(m, "permeability");
  m.species = {{"a", "", 1.0}};
  m.parameters = {{"a", 1.0}};
  fails(m, "parameter 'a' is named twice");
  m.parameters = {{"k", 1.0}};
  m.pin.species = "b";
  fails(m, "'b', which is not a species");
  m.pin.species = "a";
  m.pin.base = -1;
  fails(m, "PIN base");
  m.pin.base = 2;
  REQUIRE_NOTHROW(m.validate());
}

TEST_CASE("A reaction that does not parse names its species", "[networks]") {
  NetworkModel m = testing::oneSpecies("a", 0.0, "a * unknown_name");
  const NetworkGraph g = testing::chainGraph({1.0, 1.0}, {1.0});
  REQUIRE_THROWS_WITH(NetworkSystem(m, g), Catch::Contains("species 'a'") && Catch::Contains("unknown_name"));
  m.species[0].reaction = "1 / (a - a)";
  NetworkSystem system(m, g);
  std::vector<double> y{1.0, 1.0}, ydot(2);
  REQUIRE_THROWS_WITH(system.rhs(0.0, y, ydot), Catch::Contains("species 'a'") && Catch::Contains("cell 0"));
}
