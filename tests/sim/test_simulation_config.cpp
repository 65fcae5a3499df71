// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>

#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/sim/sections/tessella_schema.hpp"
#include "test_support.hpp"

using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using tessella::sim::test::ScratchDir;
using Catch::Matchers::Contains;

TEST_CASE("a minimal config gets every default", "[sim][config]") {
  const SimulationConfig s = loadSimulationConfigString("tissue: {generator: hexagonal_grid}\nrng_seed: 12\n");
  const auto& spec = std::get<GeneratorSpec>(s.tissue);
  REQUIRE(spec.name == "hexagonal_grid");
  const tessella::ParamValues& hex = spec.params;
  CHECK(hex.getInt("nx") == 10);
  CHECK(hex.getInt("ny") == 10);
  CHECK(hex.getFloat("radius") == 1.0);
  CHECK(s.time.start == 0.0);
  CHECK(s.time.end == 10.0);
  CHECK(s.time.dt == 1.0);
  CHECK(s.output.every == 1);
  CHECK(s.output.name == "tissue");
  CHECK(s.output.directory.empty());
  CHECK(s.rng_seed == 12);
  CHECK(s.config.getString("tessella_version") == tessellaVersion());
}

TEST_CASE("an absent rng_seed is drawn once and recorded", "[sim][config]") {
  const SimulationConfig a = loadSimulationConfigString("tissue: {generator: hexagonal_grid}\n");
  REQUIRE(a.config.has("rng_seed"));
  CHECK(a.config.entry("rng_seed").origin == ValueOrigin::Derived);
  CHECK(static_cast<std::uint64_t>(a.config.getInt("rng_seed")) == a.rng_seed);
  CHECK(a.config.getInt("rng_seed") >= 0);
}

TEST_CASE("every generator's section is read into its spec", "[sim][config]") {
  SECTION("rectangular grid") {
    const auto s = loadSimulationConfigString(
        "tissue:\n  generator: rectangular_grid\n  rectangular_grid: {nx: 3, ny: 2, dx: 0.5, dy: 2, origin: [1, 1]}\n");
    const auto& spec = std::get<GeneratorSpec>(s.tissue);
    REQUIRE(spec.name == "rectangular_grid");
    const tessella::ParamValues& g = spec.params;
    CHECK(g.getInt("nx") == 3);
    CHECK(g.getInt("ny") == 2);
    CHECK(g.getFloat("dx") == 0.5);
    CHECK(g.getFloat("dy") == 2.0);
    CHECK(g.getVec3("origin") == tessella::Vec3(1, 1, 0));
  }
  SECTION("box grid") {
    const auto s = loadSimulationConfigString("tissue:\n  generator: box_grid\n  box_grid: {nz: 2, dz: 3}\n");
    const auto& spec = std::get<GeneratorSpec>(s.tissue);
    REQUIRE(spec.name == "box_grid");
    const tessella::ParamValues& g = spec.params;
    CHECK(g.getInt("nx") == 4);
    CHECK(g.getInt("nz") == 2);
    CHECK(g.getFloat("dz") == 3.0);
  }
  SECTION("voronoi in a ball") {
    const auto s = loadSimulationConfigString(
        "tissue:\n  generator: voronoi\n  voronoi:\n    domain: ball\n    count: 20\n    lloyd_iterations: 2\n"
        "    ball: {radius: 3, subdivisions: 2}\n");
    const auto& v = std::get<GeneratorSpec>(s.tissue);
    REQUIRE(v.name == "voronoi");
    CHECK(v.shape().dim == 3);
    CHECK(v.params.getInt("count") == 20);
    CHECK_FALSE(v.params.has("seed_file"));
    CHECK(v.params.getInt("lloyd_iterations") == 2);
    REQUIRE(v.params.getString("domain") == "ball");
    CHECK(v.params.getFloat("ball.radius") == 3.0);
    CHECK(v.params.getInt("ball.subdivisions") == 2);
  }
  SECTION("dome") {
    const auto s = loadSimulationConfigString(
        "tissue:\n  generator: dome\n  dome: {shape: paraboloid, base_radius: 4, height: 6, count: 30}\n");
    const auto& d = std::get<GeneratorSpec>(s.tissue);
    REQUIRE(d.name == "dome");
    const std::optional<tessella::Dome> dome = tissueDome(s.tissue);
    REQUIRE(dome);
    CHECK(dome->shape == tessella::Dome::Shape::Paraboloid);
    CHECK(dome->base_radius == 4.0);
    CHECK(dome->height == 6.0);
    CHECK(d.params.getInt("count") == 30);
  }
}

TEST_CASE("checks across keys are located at the offending key", "[sim][config]") {
  SECTION("rectangle max must exceed min") {
    const ConfigError e = configErrorOf([] {
      loadSimulationConfigString(
          "tissue:\n  generator: voronoi\n  voronoi:\n    rectangle:\n      min: [0, 0]\n      max: [5, 0]\n");
    });
    CHECK(e.keyPath() == "tissue.voronoi.rectangle.max");
    CHECK(e.where().line == 6);
    CHECK_THAT(e.what(), Contains("must exceed tissue.voronoi.rectangle.min = [0.0, 0.0]") &&
                             Contains("[5.0, 0.0]"));
  }
  SECTION("count and seed_file exclude each other") {
    ScratchDir dir;
    dir.write("s.csv", "0,0\n1,0\n0,1\n");
    const std::string file =
        dir.write("c.yaml", "tissue:\n  generator: voronoi\n  voronoi: {count: 5, seed_file: s.csv}\n");
    const ConfigError e = configErrorOf([&] { loadSimulationConfigFile(file); });
    CHECK(e.keyPath() == "tissue.voronoi.count");
    CHECK_THAT(e.what(), Contains("c.yaml:3:20") && Contains("not both"));
  }
  SECTION("3D Voronoi needs 4 seeds") {
    const ConfigError e = configErrorOf([] {
      loadSimulationConfigString("tissue:\n  generator: voronoi\n  voronoi: {domain: box, count: 3}\n");
    });
    CHECK_THAT(e.what(), Contains("tissue.voronoi.count") && Contains("at least 4 seeds, got 3"));
  }
  SECTION("time.end before time.start") {
    const ConfigError e = configErrorOf([] {
      loadSimulationConfigString("tissue: {generator: hexagonal_grid}\ntime:\n  start: 5\n  end: 2\n");
    });
    CHECK(e.keyPath() == "time.end");
    CHECK_THAT(e.what(), Contains("<string>:4:8") && Contains("must be >= time.start (5.0), got 2.0"));
  }
  SECTION("a dt that would take forever") {
    const ConfigError e = configErrorOf([] {
      loadSimulationConfigString("tissue: {generator: hexagonal_grid}\ntime: {end: 1e6, dt: 1e-6}\n");
    });
    CHECK_THAT(e.what(), Contains("time.dt") && Contains("more than the limit"));
  }
  SECTION("a grid too large to allocate") {
    const ConfigError e = configErrorOf([] {
      loadSimulationConfigString("tissue:\n  generator: rectangular_grid\n  rectangular_grid: {nx: 100000, ny: 1000}\n");
    });
    CHECK_THAT(e.what(), Contains("tissue.rectangular_grid.nx") && Contains("nx * ny = 1e+08 cells"));
  }
  SECTION("a spherical cap higher than wide") {
    const ConfigError e = configErrorOf([] {
      loadSimulationConfigString("tissue:\n  generator: dome\n  dome: {base_radius: 2, height: 3}\n");
    });
    CHECK_THAT(e.what(), Contains("tissue.dome.height") && Contains("paraboloid"));
  }
  SECTION("a series name with a path separator") {
    const ConfigError e = configErrorOf([] {
      loadSimulationConfigString("tissue: {generator: hexagonal_grid}\noutput: {name: ../evil}\n");
    });
    CHECK_THAT(e.what(), Contains("output.name") && Contains("'../evil'"));
  }
}

TEST_CASE("the brief's bad configs, on the real schema", "[sim][config]") {
  ScratchDir dir;
  SECTION("unknown key") {
    const std::string f = dir.write("bad.yaml", "tissue:\n  generator: voronoi\n  voronoi:\n    cuont: 20\n");
    const ConfigError e = configErrorOf([&] { loadSimulationConfigFile(f); });
    CHECK(e.keyPath() == "tissue.voronoi.cuont");
    CHECK_THAT(e.what(), Contains("bad.yaml:4:5") && Contains("did you mean 'count'?"));
  }
  SECTION("wrong type") {
    const std::string f = dir.write("bad.yaml", "tissue:\n  generator: voronoi\n  voronoi:\n    count: many\n");
    const ConfigError e = configErrorOf([&] { loadSimulationConfigFile(f); });
    CHECK_THAT(e.what(), Contains("bad.yaml:4:12: tissue.voronoi.count: expected an integer >= 3") &&
                             Contains("got 'many'"));
  }
  SECTION("out of range") {
    const std::string f = dir.write("bad.yaml", "tissue:\n  generator: voronoi\n  voronoi:\n    count: 2\n");
    const ConfigError e = configErrorOf([&] { loadSimulationConfigFile(f); });
    CHECK_THAT(e.what(), Contains("bad.yaml:4:12: tissue.voronoi.count: value 2 is out of range"));
  }
  SECTION("unknown generator") {
    const std::string f = dir.write("bad.yaml", "tissue:\n  generator: hexagon_grid\n");
    const ConfigError e = configErrorOf([&] { loadSimulationConfigFile(f); });
    CHECK_THAT(e.what(), Contains("bad.yaml:2:14: tissue.generator") && Contains("did you mean 'hexagonal_grid'?"));
  }
  SECTION("missing generator") {
    const std::string f = dir.write("bad.yaml", "time: {end: 3}\n");
    const ConfigError e = configErrorOf([&] { loadSimulationConfigFile(f); });
    CHECK_THAT(e.what(), Contains("bad.yaml") && Contains("tissue.generator: missing required key"));
  }
  SECTION("bad --set") {
    const std::string f = dir.write("ok.yaml", "tissue:\n  generator: voronoi\n");
    const ConfigError e = configErrorOf([&] { loadSimulationConfigFile(f, {"tissue.voronoi.count=-4"}); });
    CHECK_THAT(e.what(), Contains("--set tissue.voronoi.count=-4: tissue.voronoi.count: value -4 is out of range"));
  }
}
