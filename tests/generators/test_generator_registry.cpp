// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The generator table: every entry builds from its defaults what its shape()
// announces, parameters reach the generator functions unchanged, and checks
// across parameters blame the right one.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "tessella/generators/dome.hpp"
#include "tessella/generators/generator_registry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using Catch::Matchers::Contains;

namespace {

// The parameter a ParamError blames, or "" when `make` throws something else or nothing.
template <typename Make>
std::string blamed(Make make) {
  try {
    make();
  } catch (const ParamError& e) {
    return e.param();
  } catch (...) {
  }
  return "";
}

ParamValues completed(const std::string& name, const ParamValues& values) {
  return completeParams(generators().at(name).params, values, name);
}

}  // namespace

TEST_CASE("every generator builds, from its defaults, the tissue its shape announces", "[generators][registry]") {
  CHECK(generators().names() ==
        std::vector<std::string>{"rectangular_grid", "hexagonal_grid", "box_grid", "cylinder", "voronoi", "dome"});
  for (const auto& g : generators().entries()) {
    INFO(g.name);
    const GeneratedShape shape = g.make.shape(completed(g.name, {}));
    const Tissue t = generators().make(g.name, {}, 7);
    CHECK(t.dim() == shape.dim);
    CHECK(t.embedding() == shape.embedding);
    CHECK(t.numCells() > 0);
    CHECK(validate(t).ok);
  }
  for (const std::string domain : {"rectangle", "disk", "box", "ball"}) {
    INFO(domain);
    const ParamValues p = completed("voronoi", {{"domain", domain}, {"count", std::int64_t{20}}});
    const GeneratedShape shape = generators().at("voronoi").make.shape(p);
    CHECK(shape.decided_by == "domain");
    const Tissue t = generators().make("voronoi", p, 3);
    CHECK(t.dim() == shape.dim);
    CHECK(t.embedding() == shape.embedding);
    CHECK(t.numCells() == 20);
  }
}

TEST_CASE("a generator's entry passes its parameters to the generator function unchanged", "[generators][registry]") {
  const Tissue hex = generators().make(
      "hexagonal_grid", {{"nx", std::int64_t{3}}, {"radius", 0.5}, {"origin", std::vector<double>{1, 2}}}, 0);
  const Tissue direct = hexagonalGrid(3, 10, 0.5, Vec3(1, 2, 0));
  REQUIRE(hex.numVertices() == direct.numVertices());
  for (VertexId v : hex.vertices()) CHECK(hex.position(v) == direct.position(v));

  const Tissue ball = generators().make(
      "voronoi", {{"domain", std::string("ball")}, {"count", std::int64_t{30}}, {"ball.radius", 1.5},
                  {"ball.subdivisions", std::int64_t{2}}, {"lloyd_iterations", std::int64_t{1}}},
      11);
  const Ball domain{Vec3::Zero(), 1.5, 2};
  const Tissue expected = voronoiTissue(randomSeeds(domain, 30, 11), domain, {.lloyd_iterations = 1});
  REQUIRE(ball.numVertices() == expected.numVertices());
  for (VertexId v : ball.vertices()) CHECK(ball.position(v) == expected.position(v));

  const ParamValues dome_params = completed("dome", {{"shape", std::string("paraboloid")}, {"height", 6.0}});
  const std::optional<Dome> dome = generators().at("dome").make.dome(dome_params);
  REQUIRE(dome);
  CHECK(dome->shape == Dome::Shape::Paraboloid);
  CHECK(dome->height == 6.0);
  CHECK(dome->base_radius == 5.0);
  CHECK_FALSE(generators().at("voronoi").make.dome);
}

TEST_CASE("checks across a generator's parameters blame one of them", "[generators][registry]") {
  const ParamValues huge{{"nx", std::int64_t{100000}}, {"ny", std::int64_t{1000}}};
  CHECK(blamed([&] { generators().make("rectangular_grid", huge, 0); }) == "nx");
  const ParamValues box{{"nx", std::int64_t{1000}}, {"ny", std::int64_t{1000}}, {"nz", std::int64_t{40}}};
  CHECK_THROWS_WITH(generators().make("box_grid", box, 0),
                    Contains("nx * ny * nz = 4e+07 cells is more than the limit of 1e+07"));
  const ParamValues flat{{"rectangle.min", std::vector<double>{0, 0}}, {"rectangle.max", std::vector<double>{5, 0}}};
  CHECK(blamed([&] { generators().make("voronoi", flat, 0); }) == "rectangle.max");
  const ParamValues few{{"domain", std::string("box")}, {"count", std::int64_t{3}}};
  CHECK(blamed([&] { generators().make("voronoi", few, 0); }) == "count");
  CHECK(blamed([] { generators().make("dome", {{"height", 6.0}}, 0); }) == "height");

  // count and seed_file exclude each other; a bad seed file is blamed on seed_file.
  const auto path = std::filesystem::temp_directory_path() / "tessella_test_registry_seeds.csv";
  std::ofstream(path) << "0,0\n1,0\n0,1\n20,20\n";
  const ParamValues both{{"count", std::int64_t{5}}, {"seed_file", path.string()}};
  CHECK(blamed([&] { generators().make("voronoi", both, 0); }) == "count");
  CHECK_THROWS_WITH(generators().make("voronoi", both, 0), Contains("give either count or seed_file, not both"));
  // The fourth seed lies outside the default rectangle [0, 10]^2.
  CHECK(blamed([&] { generators().make("voronoi", {{"seed_file", path.string()}}, 0); }) == "seed_file");
  std::filesystem::remove(path);

  CHECK_THROWS_WITH(generators().make("hexagon", {}, 0),
                    Contains("unknown generator 'hexagon'") && Contains("hexagonal_grid"));
}
