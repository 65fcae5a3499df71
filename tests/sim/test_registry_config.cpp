// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Registries in the configuration (sim/config/registry_config.hpp): the keys
// declared from a table, the values read back, errors at the right key.
#include <catch2/catch.hpp>

#include <functional>

#include "tessella/sim/config/config_loader.hpp"
#include "tessella/sim/config/registry_config.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using Catch::Matchers::Contains;

namespace {

using Factory = std::function<double(const ParamValues&)>;

// Two entries sharing the parameter `scale`; `fussy` refuses odd sides itself.
const Registry<Factory>& shapes() {
  static const Registry<Factory> table(
      "shape",
      {{"square", "A square.",
        {ParamSpec("side", ParamType::Float, "Side.").byDefault(1.0).above(0),
         ParamSpec("scale", ParamType::Float, "Scale.").byDefault(1.0)},
        [](const ParamValues& p) { return p.getFloat("scale") * p.getFloat("side") * p.getFloat("side"); }},
       {"fussy", "Even sides only.",
        {ParamSpec("sides", ParamType::Int, "Sides.").byDefault(std::int64_t{4}),
         ParamSpec("scale", ParamType::Float, "Scale.").byDefault(1.0)},
        [](const ParamValues& p) {
          if (p.getInt("sides") % 2) throw ParamError("sides", "sides must be even");
          if (p.getFloat("scale") > 10) throw InputError("too big");
          return p.getFloat("scale");
        }},
       {"dot", "No parameters.", {}, [](const ParamValues&) { return 0.0; }}});
  return table;
}

Schema schema(bool flat) {
  Schema s;
  s.section("shape", "A shape.");
  s.key("shape.kind", ValueType::Enum, "Kind. " + choicesDoc(shapes()))
      .oneOf(withNone(shapes().names()))
      .byDefault(std::string("none"));
  if (flat)
    declareEntryKeys(s, "shape", "shape.kind", shapes());
  else
    declareEntrySections(s, "shape", "shape.kind", shapes());
  return s;
}

}  // namespace

TEST_CASE("a table's parameters become keys, in sections or flat", "[sim][config][registry]") {
  const Schema nested = schema(false), flat = schema(true);
  CHECK(nested.findKey("shape.square.side"));
  CHECK(nested.findKey("shape.fussy.scale"));
  CHECK_FALSE(nested.findSection("shape.dot"));  // no parameters, no section
  REQUIRE(nested.findSection("shape.square"));
  CHECK(nested.findSection("shape.square")->doc == "A square.");
  CHECK(nested.findKey("shape.kind")->doc ==
        "Kind. `square`: A square. `fussy`: Even sides only. `dot`: No parameters.");
  // Flat: the shared `scale` is one key, active for both entries that read it.
  const KeySpec* scale = flat.findKey("shape.scale");
  REQUIRE(scale);
  REQUIRE(scale->active_when);
  CHECK(scale->active_when->values == std::vector<std::string>{"square", "fussy"});
  CHECK(flat.findKey("shape.sides")->active_when->values == std::vector<std::string>{"fussy"});

  // Two entries declaring one flat key differently is a programming error.
  const Registry<Factory> clash("shape", {{"a", "", {ParamSpec("x", ParamType::Float, "X.").byDefault(1.0)}, {}},
                                          {"b", "", {ParamSpec("x", ParamType::Float, "X.").byDefault(2.0)}, {}}});
  Schema s;
  s.section("shape", "");
  s.key("shape.kind", ValueType::Enum, "").oneOf({"a", "b"}).byDefault(std::string("a"));
  CHECK_THROWS_AS(declareEntryKeys(s, "shape", "shape.kind", clash), std::logic_error);
}

TEST_CASE("an entry is made from the config; its errors point at their key", "[sim][config][registry]") {
  const Schema nested = schema(false), flat = schema(true);
  const auto make = [](const Schema& s, const std::string& yaml, const std::string& section) {
    const Config c = loadConfigString(yaml, {}, s);
    const std::string kind = c.getString("shape.kind");
    return makeFromConfig(c, shapes(), kind, section.empty() ? "shape." + kind : section, "shape.kind");
  };
  CHECK(make(nested, "shape: {kind: square, square: {side: 2.0}}", "") == 4.0);
  CHECK(make(flat, "shape: {kind: square, side: 3.0, scale: 2.0}", "shape") == 18.0);
  CHECK(make(nested, "shape: {kind: dot}", "") == 0.0);
  // Config::params reads the entry's own keys only.
  const Config c = loadConfigString("shape: {kind: fussy, scale: 3.0}", {}, flat);
  const ParamValues values = c.params("shape", shapes().at("fussy").params);
  CHECK(values.all().size() == 2);
  CHECK(values.getFloat("scale") == 3.0);
  CHECK(values.getInt("sides") == 4);

  const ConfigError odd = configErrorOf([&] { make(nested, "shape: {kind: fussy, fussy: {sides: 3}}", ""); });
  CHECK(odd.keyPath() == "shape.fussy.sides");
  CHECK_THAT(odd.what(), Contains("sides must be even"));
  const ConfigError big = configErrorOf([&] { make(flat, "shape: {kind: fussy, scale: 11.0}", "shape"); });
  CHECK(big.keyPath() == "shape.kind");
  CHECK_THAT(big.what(), Contains("too big"));
}
