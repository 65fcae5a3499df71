// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <filesystem>

#include "tessella/sim/config/config_loader.hpp"
#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/sim/sections/tessella_schema.hpp"
#include "test_support.hpp"

using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using tessella::sim::test::ScratchDir;
using Catch::Matchers::Contains;

namespace {

// A small schema exercising every value type and a condition.
Schema demoSchema() {
  Schema s;
  s.key("flag", ValueType::Bool, "a flag").byDefault(false);
  s.section("shape", "a shape");
  s.key("shape.kind", ValueType::Enum, "kind").oneOf({"circle", "square"}).byDefault(std::string("circle"));
  s.key("shape.sides", ValueType::Int, "sides").byDefault(std::int64_t{4}).atLeast(3).atMost(12);
  s.key("shape.scale", ValueType::Float, "scale").byDefault(1.0).above(0);
  s.key("shape.name", ValueType::String, "name").isRequired();
  s.key("shape.center", ValueType::Vec2, "centre").byDefault(std::vector<double>{0, 0});
  s.section("shape.circle", "circle only").activeWhen("shape.kind", {"circle"});
  s.key("shape.circle.radius", ValueType::Float, "radius").byDefault(2.0).above(0);
  return s;
}

Config loadDemo(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  static const Schema schema = demoSchema();
  return loadConfigString(yaml, overrides, schema, "demo", "demo.yaml", ".");
}

}  // namespace

TEST_CASE("values are typed, defaults filled and origins recorded", "[sim][config]") {
  const Config c = loadDemo(
      "flag: yes\n"
      "shape:\n"
      "  name: petal\n"
      "  sides: 6\n"
      "  center: [1.5, -2]\n");
  CHECK(c.getBool("flag"));
  CHECK(c.getInt("shape.sides") == 6);
  CHECK(c.getFloat("shape.scale") == 1.0);
  CHECK(c.getString("shape.name") == "petal");
  CHECK(c.getVec("shape.center") == tessella::Vec3(1.5, -2, 0));
  CHECK(c.isGiven("shape.sides"));
  CHECK_FALSE(c.isGiven("shape.scale"));
  CHECK(c.entry("shape.scale").origin == ValueOrigin::Default);
  // Positions point at the value: line 4, column 10 ("  sides: 6").
  CHECK(c.entry("shape.sides").where.line == 4);
  CHECK(c.entry("shape.sides").where.column == 10);
  CHECK(c.entry("shape.sides").where.file == "demo.yaml");
}

TEST_CASE("conditional sections are active only under their condition", "[sim][config]") {
  const Config circle = loadDemo("shape: {name: a}\n");
  CHECK(circle.isActive("shape.circle.radius"));
  const Config square = loadDemo("shape: {name: a, kind: square, circle: {radius: 3}}\n");
  CHECK_FALSE(square.isActive("shape.circle"));
  CHECK_FALSE(square.isActive("shape.circle.radius"));
  REQUIRE(square.notes().size() == 1);
  CHECK_THAT(square.notes()[0], Contains("shape.circle is ignored: shape.kind is square"));
}

TEST_CASE("overrides replace file values and are checked the same way", "[sim][config]") {
  const Config c = loadDemo("shape: {name: a, sides: 5}\n", {"shape.sides=7", "shape.center=[3, 4]"});
  CHECK(c.getInt("shape.sides") == 7);
  CHECK(c.getVec("shape.center") == tessella::Vec3(3, 4, 0));
  CHECK(c.entry("shape.sides").origin == ValueOrigin::Override);

  const Config section = loadDemo("shape: {name: a}\n", {"shape={name: b, scale: 2.5}"});
  CHECK(section.getString("shape.name") == "b");
  CHECK(section.getFloat("shape.scale") == 2.5);

  const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a}\n", {"shape.sides=13"}); });
  CHECK(e.keyPath() == "shape.sides");
  CHECK_THAT(e.what(), Contains("--set shape.sides=13") && Contains("out of range") && Contains("13"));
}

TEST_CASE("every kind of bad value is a located ConfigError", "[sim][config]") {
  SECTION("wrong scalar type") {
    const ConfigError e = configErrorOf([] { loadDemo("shape:\n  name: a\n  sides: six\n"); });
    CHECK(e.keyPath() == "shape.sides");
    CHECK(e.where().line == 3);
    CHECK(e.where().column == 10);
    CHECK_THAT(e.what(), Contains("demo.yaml:3:10") && Contains("expected an integer") && Contains("'six'"));
  }
  SECTION("a float where an integer is expected") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a, sides: 4.5}\n"); });
    CHECK_THAT(e.what(), Contains("shape.sides") && Contains("'4.5'"));
  }
  SECTION("a mapping where a value is expected") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a, scale: {x: 1}}\n"); });
    CHECK_THAT(e.what(), Contains("shape.scale") && Contains("got a mapping"));
  }
  SECTION("a value where a section is expected") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: 3\n"); });
    CHECK_THAT(e.what(), Contains("demo.yaml:1:8") && Contains("shape") && Contains("expected a section"));
  }
  SECTION("exclusive lower bound") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a, scale: 0}\n"); });
    CHECK_THAT(e.what(), Contains("shape.scale") && Contains("value 0 is out of range") && Contains("> 0"));
  }
  SECTION("non-finite float") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a, scale: .inf}\n"); });
    CHECK_THAT(e.what(), Contains("shape.scale") && Contains("'.inf'"));
  }
  SECTION("misspelt enum value") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a, kind: sqare}\n"); });
    CHECK_THAT(e.what(), Contains("one of circle, square") && Contains("did you mean 'square'"));
  }
  SECTION("vector of the wrong length") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a, center: [1, 2, 3]}\n"); });
    CHECK_THAT(e.what(), Contains("shape.center") && Contains("a sequence of 3"));
  }
  SECTION("vector with a non-number names the element") {
    const ConfigError e = configErrorOf([] { loadDemo("shape:\n  name: a\n  center: [1, up]\n"); });
    CHECK(e.keyPath() == "shape.center[1]");
    CHECK_THAT(e.what(), Contains("demo.yaml:3:15") && Contains("'up'"));
  }
  SECTION("bad boolean") {
    const ConfigError e = configErrorOf([] { loadDemo("flag: maybe\nshape: {name: a}\n"); });
    CHECK_THAT(e.what(), Contains("demo.yaml:1:7") && Contains("flag") && Contains("true or false"));
  }
  SECTION("empty value") {
    const ConfigError e = configErrorOf([] { loadDemo("shape:\n  name: a\n  sides:\n"); });
    CHECK_THAT(e.what(), Contains("demo.yaml:3:3") && Contains("shape.sides") && Contains("no value given"));
  }
  SECTION("missing required key points at its section") {
    const ConfigError e = configErrorOf([] { loadDemo("flag: true\nshape:\n  sides: 5\n"); });
    CHECK(e.keyPath() == "shape.name");
    CHECK_THAT(e.what(), Contains("demo.yaml:3:3") && Contains("missing required key"));
  }
  SECTION("duplicate key") {
    const ConfigError e = configErrorOf([] { loadDemo("shape:\n  name: a\n  sides: 5\n  sides: 6\n"); });
    CHECK_THAT(e.what(), Contains("demo.yaml:4:3") && Contains("shape.sides") && Contains("duplicate key") &&
                             Contains("3:3"));
  }
  SECTION("unknown key with a suggestion") {
    const ConfigError e = configErrorOf([] { loadDemo("shape:\n  name: a\n  sieds: 5\n"); });
    CHECK(e.keyPath() == "shape.sieds");
    CHECK_THAT(e.what(), Contains("demo.yaml:3:3") && Contains("did you mean 'sides'?"));
  }
  SECTION("a known key in the wrong section") {
    const ConfigError e = configErrorOf([] { loadDemo("radius: 2\nshape: {name: a}\n"); });
    CHECK_THAT(e.what(), Contains("unknown key 'radius'") && Contains("did you mean 'shape.circle.radius'?"));
  }
  SECTION("unknown key without a close match lists the known ones") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a, velocity: 2}\n"); });
    CHECK_THAT(e.what(), Contains("known keys here: kind, sides, scale, name, center, circle"));
  }
  SECTION("malformed YAML") {
    const ConfigError e = configErrorOf([] { loadDemo("shape:\n  name: [a, b\n  sides: 3\n"); });
    CHECK(e.where().line > 0);
    CHECK_THAT(e.what(), Contains("demo.yaml:") && Contains("malformed YAML"));
  }
  SECTION("a top level that is not a mapping") {
    const ConfigError e = configErrorOf([] { loadDemo("- a\n- b\n"); });
    CHECK_THAT(e.what(), Contains("demo.yaml:1:1") && Contains("top level must be a mapping"));
  }
  SECTION("a second YAML document is refused at its '---', not ignored") {
    ConfigError e = configErrorOf([] { loadDemo("shape:\n  name: a\n---\nshape:\n  sides: 5\n"); });
    CHECK(e.where().line == 3);
    CHECK_THAT(e.what(), Contains("demo.yaml:3:1") && Contains("a second YAML document"));
    // Also when the first document has its own marker, the second is empty or starts on the marker line.
    e = configErrorOf([] { loadDemo("---\nshape: {name: a}\n---\n# nothing\n"); });
    CHECK(e.where().line == 3);
    e = configErrorOf([] { loadDemo("shape: {name: a}\n--- {flag: true}\n"); });
    CHECK(e.where().line == 2);
    // One document with a leading marker, or closed by '...', is fine.
    CHECK(loadDemo("---\nshape: {name: a}\n...\n").getString("shape.name") == "a");
  }
}

TEST_CASE("bad --set arguments name the argument", "[sim][config]") {
  SECTION("no '='") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a}\n", {"shape.sides"}); });
    CHECK_THAT(e.what(), Contains("--set shape.sides") && Contains("KEY.PATH=VALUE"));
  }
  SECTION("misspelt path gets a full-path suggestion") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a}\n", {"shape.sieds=5"}); });
    CHECK(e.keyPath() == "shape.sieds");
    CHECK_THAT(e.what(), Contains("--set shape.sieds=5") && Contains("did you mean 'shape.sides'?"));
  }
  SECTION("misspelt section") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a}\n", {"shap.circle.radius=5"}); });
    CHECK_THAT(e.what(), Contains("did you mean 'shape.circle.radius'?"));
  }
  SECTION("path through a value") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a}\n", {"shape.sides.x=5"}); });
    CHECK_THAT(e.what(), Contains("shape.sides is a value, not a section"));
  }
  SECTION("malformed YAML value") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a}\n", {"shape.center=[1, 2"}); });
    CHECK_THAT(e.what(), Contains("--set shape.center=[1, 2") && Contains("not valid YAML"));
  }
  SECTION("wrong type") {
    const ConfigError e = configErrorOf([] { loadDemo("shape: {name: a}\n", {"shape.scale=big"}); });
    CHECK_THAT(e.what(), Contains("--set shape.scale=big: shape.scale: expected a number > 0, got 'big'"));
  }
}

TEST_CASE("Path keys resolve relative to the config file and must exist", "[sim][config]") {
  ScratchDir dir;
  std::filesystem::create_directories(dir.path() / "data");
  dir.write("data/seeds.csv", "x,y\n1,1\n2,2\n3,1\n");
  const std::string config = dir.write(
      "voronoi.yaml",
      "tissue:\n  generator: voronoi\n  voronoi:\n    seed_file: data/seeds.csv\n");
  const Config c = loadConfigFile(config, {}, tessellaSchema());
  CHECK(c.getString("tissue.voronoi.seed_file") == (dir.path() / "data" / "seeds.csv").string());
  CHECK(c.name() == "voronoi");

  const std::string missing = dir.write(
      "missing.yaml",
      "tissue:\n  generator: voronoi\n  voronoi:\n    seed_file: data/nowhere.csv\n");
  const ConfigError e = configErrorOf([&] { loadConfigFile(missing, {}, tessellaSchema()); });
  CHECK(e.keyPath() == "tissue.voronoi.seed_file");
  CHECK(e.where().line == 4);
  CHECK(e.where().column == 16);
  CHECK_THAT(e.what(), Contains("missing.yaml:4:16") && Contains("file not found") &&
                           Contains("data/nowhere.csv"));
}

TEST_CASE("a missing config file is a ConfigError naming it", "[sim][config]") {
  ScratchDir dir;
  const ConfigError e = configErrorOf([&] { loadConfigFile(dir / "absent.yaml", {}, tessellaSchema()); });
  CHECK_THAT(e.what(), Contains("absent.yaml") && Contains("not found"));
}
