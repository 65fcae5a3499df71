// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Registry and parameter tables: defaults, type and range checks, messages
// that name the entry, the parameter and the value.
#include <catch2/catch.hpp>
#include <functional>
#include <limits>

#include "tessella/tissue/enum_table.hpp"
#include "tessella/tissue/registry.hpp"

using namespace tessella;
using Catch::Matchers::Contains;

namespace {
using Factory = std::function<double(const ParamValues&, double)>;

const Registry<Factory>& shapes() {
  static const Registry<Factory> registry(
      "shape", {{"square", "A square of side `side`.",
                 {ParamSpec("side", ParamType::Float, "Side length.").byDefault(1.0).above(0)},
                 [](const ParamValues& p, double scale) { return scale * p.getFloat("side") * p.getFloat("side"); }},
                {"grid", "n x n unit squares.",
                 {ParamSpec("n", ParamType::Int, "Cells per side.").atLeast(1).atMost(10),
                  ParamSpec("kind", ParamType::Enum, "Cell kind.").oneOf({"quad", "hex"}).byDefault(std::string("quad")),
                  ParamSpec("origin", ParamType::Vec3, "Corner.").byDefault(std::vector<double>{0, 0, 0})},
                 [](const ParamValues& p, double) {
                   return static_cast<double>(p.getInt("n") * p.getInt("n")) + p.getVec3("origin").x();
                 }}});
  return registry;
}
}  // namespace

TEST_CASE("a registry lists its entries in table order and makes them with defaults filled in", "[registry]") {
  CHECK(shapes().names() == std::vector<std::string>{"square", "grid"});
  CHECK(shapes().namesText() == "square, grid");
  CHECK(shapes().make("square", {}, 2.0) == 2.0);
  CHECK(shapes().make("square", {{"side", 3.0}}, 1.0) == 9.0);
  // An integer where a float is expected is converted.
  CHECK(shapes().make("square", {{"side", std::int64_t{2}}}, 1.0) == 4.0);
  CHECK(shapes().make("grid", {{"n", std::int64_t{3}}, {"origin", std::vector<double>{0.5, 0, 0}}}, 1.0) == 9.5);
}

TEST_CASE("a registry refuses unknown names, unknown, missing, mistyped and out-of-range parameters", "[registry]") {
  CHECK_THROWS_WITH(shapes().make("circle", {}, 1.0),
                    Contains("unknown shape 'circle'") && Contains("known: square, grid"));
  CHECK_THROWS_WITH(shapes().make("square", {{"sides", 2.0}}, 1.0),
                    Contains("shape 'square' has no parameter 'sides'") && Contains("known: side"));
  CHECK_THROWS_WITH(shapes().make("square", {{"side", 0.0}}, 1.0),
                    Contains("parameter 'side' must be a number > 0, got 0.0"));
  CHECK_THROWS_WITH(shapes().make("square", {{"side", std::string("big")}}, 1.0),
                    Contains("must be a number, got big"));
  CHECK_THROWS_WITH(shapes().make("grid", {}, 1.0), Contains("shape 'grid': parameter 'n' is required"));
  CHECK_THROWS_WITH(shapes().make("grid", {{"n", std::int64_t{11}}}, 1.0),
                    Contains("must be a number >= 1 and <= 10, got 11"));
  CHECK_THROWS_WITH(shapes().make("grid", {{"n", 2.5}}, 1.0), Contains("must be an integer, got 2.5"));
  CHECK_THROWS_WITH(shapes().make("grid", {{"n", std::int64_t{2}}, {"kind", std::string("tri")}}, 1.0),
                    Contains("must be one of quad, hex, got tri"));
  CHECK_THROWS_WITH(shapes().make("grid", {{"n", std::int64_t{2}}, {"origin", std::vector<double>{1, 2}}}, 1.0),
                    Contains("must be a list of 3 numbers, got [1.0, 2.0]"));
  CHECK_THROWS_AS(shapes().make("square", {{"side", std::numeric_limits<double>::infinity()}}, 1.0), InputError);
}

TEST_CASE("a duplicate registry entry is a programming error", "[registry]") {
  using F = std::function<int(const ParamValues&)>;
  CHECK_THROWS_AS(Registry<F>("thing", {{"a", "", {}, [](const ParamValues&) { return 1; }},
                                        {"a", "", {}, [](const ParamValues&) { return 2; }}}),
                  std::logic_error);
}

TEST_CASE("numbers are formatted as the shortest text that reads back", "[registry]") {
  CHECK(formatNumber(0.1) == "0.1");
  CHECK(formatNumber(1.0) == "1");
  CHECK(formatNumber(1e-8) == "1e-08");
  CHECK(formatParamValue(1.0) == "1.0");
  CHECK(formatParamValue(std::vector<double>{1, 0.5}) == "[1.0, 0.5]");
  CHECK(ParamRange{.min = 0.0, .max = 1.0, .min_exclusive = true}.text() == "> 0 and <= 1");
}

TEST_CASE("a parameter error names the parameter at fault", "[registry]") {
  try {
    shapes().make("square", {{"side", -1.0}}, 1.0);
    FAIL("no error");
  } catch (const ParamError& e) {
    CHECK(e.param() == "side");
  }
  try {
    shapes().make("grid", {}, 1.0);
    FAIL("no error");
  } catch (const ParamError& e) {
    CHECK(e.param() == "n");
    CHECK_THAT(e.what(), Contains("is required"));
  }
  // blameParam turns another InputError into a ParamError and keeps a ParamError as it is.
  CHECK_THROWS_WITH(blameParam("side", []() -> int { throw InputError("too small"); }), "too small");
  try {
    blameParam("side", []() -> int { throw InputError("too small"); });
  } catch (const ParamError& e) {
    CHECK(e.param() == "side");
  }
  try {
    blameParam("side", []() -> int { throw ParamError("n", "bad n"); });
  } catch (const ParamError& e) {
    CHECK(e.param() == "n");
  }
  CHECK(blameParam("side", [] { return 3; }) == 3);
}

TEST_CASE("an enum table names each value once and parses names and aliases", "[registry]") {
  enum class Colour { Red, Green };
  const EnumTable<Colour> colours("colour", {{"red", Colour::Red, "Warm."}, {"green", Colour::Green, "Cool."}},
                                  {{"verde", Colour::Green}});
  CHECK(colours.names() == std::vector<std::string>{"red", "green"});
  CHECK(colours.namesText() == "red, green");
  CHECK(colours.parse("green") == Colour::Green);
  CHECK(colours.parse("verde") == Colour::Green);
  CHECK(colours.name(Colour::Red) == "red");
  CHECK_THROWS_WITH(colours.parse("blue"), "unknown colour 'blue' (known: red, green, verde)");
  CHECK_THROWS_AS(EnumTable<Colour>("colour", {{"red", Colour::Red, ""}, {"red", Colour::Green, ""}}),
                  std::logic_error);
}
