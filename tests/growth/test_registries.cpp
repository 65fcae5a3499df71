// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The tables of growth/ (registries.hpp, the integrator's enum tables): every
// entry builds from its defaults, parameters reach the objects, and errors
// name the parameter at fault.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "growth_fixtures.hpp"
#include "tessella/growth/expression_field.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using namespace tessella::growth;
using Catch::Matchers::Contains;

namespace {

// The parameter a ParamError blames; "" for any other error.
template <typename Make>
std::string blamed(Make make) {
  try {
    make();
  } catch (const ParamError& e) {
    return e.param();
  } catch (const InputError&) {
    return "";
  }
  FAIL("no error");
  return "";
}

}  // namespace

TEST_CASE("the division rule table builds every rule from its defaults", "[growth][registries]") {
  const std::vector<std::string> names = divisionRuleNames();
  CHECK(names == divisionRules().names());
  const std::vector<std::string> first = {"main_axis", "shortest_wall", "perpendicular_to_mother_wall",
                                          "random", "fixed", "besson_dumais"};
  REQUIRE(names.size() >= first.size());
  CHECK(std::vector<std::string>(names.begin(), names.begin() + 6) == first);
  Tissue t = testing::rectangleCell(2.0, 1.0);
  Rng rng(1);
  for (const auto& entry : divisionRules().entries()) {
    INFO(entry.name);
    CHECK_FALSE(entry.doc.empty());
    const auto rule = makeDivisionRule(entry.name);
    CHECK(rule->name() == entry.name);
    CHECK(rule->plane(t, CellId(0), rng).normal.allFinite());
  }
}

TEST_CASE("division rule parameters reach the rule and are checked", "[growth][registries]") {
  Tissue t = testing::rectangleCell(2.0, 1.0);
  Rng rng(1);
  const auto fixed = makeDivisionRule("fixed", {{"fixed_normal", std::vector<double>{0, 2, 0}}});
  CHECK(fixed->plane(t, CellId(0), rng).normal.isApprox(Vec3::UnitY()));
  CHECK_THROWS_WITH(makeDivisionRule("main_axis", {{"beta", 1.0}}),
                    Contains("division rule 'main_axis' has no parameter 'beta'"));
  CHECK_THROWS_WITH(makeDivisionRule("besson_dumais", {{"beta", -1.0}}),
                    Contains("division rule 'besson_dumais': parameter 'beta' must be a number >= 0, got -1.0"));
  // Errors of the rule's own checks blame the parameter, for readers that point at its key.
  CHECK(blamed([] { makeDivisionRule("fixed", {{"fixed_normal", std::vector<double>{0, 0, 0}}}); }) ==
        "fixed_normal");
  CHECK(blamed([] { makeDivisionRule("besson_dumais", {{"beta", -1.0}}); }) == "beta");
  CHECK(blamed([] { makeDivisionRule("errera"); }).empty());
}

TEST_CASE("the velocity field table builds every field from its defaults", "[growth][registries]") {
  CHECK(velocityFields().names() ==
        std::vector<std::string>{"uniform", "anisotropic", "radial", "bump", "meristem", "expression"});
  for (const auto& entry : velocityFields().entries()) {
    INFO(entry.name);
    const auto field = velocityFields().make(entry.name, {});
    CHECK(field->velocity(Vec3(0.3, 0.2, 0.1), 0.5).allFinite());
    CHECK_FALSE(field->describe().empty());
  }
  const auto uniform = velocityFields().make("uniform", {{"rate", 0.3}, {"center", std::vector<double>{1, 2, 3}}});
  CHECK(uniform->velocity(Vec3(2, 2, 3), 0.0).isApprox(Vec3(0.3, 0, 0)));
  const auto expression =
      velocityFields().make("expression", {{"vx", std::string("r*x")}, {"parameters", std::string("r = 0.5")}});
  CHECK(expression->velocity(Vec3(2, 0, 0), 0.0).isApprox(Vec3(1, 0, 0)));
}

TEST_CASE("velocity field errors blame the parameter at fault", "[growth][registries]") {
  const auto make = [](ParamValues p) { return [p] { velocityFields().make("expression", p); }; };
  CHECK(blamed(make({{"vy", std::string("2*/y")}})) == "vy");
  CHECK(blamed(make({{"vx", std::string("r*x")}, {"parameters", std::string("r=abc")}})) == "parameters");
  CHECK(blamed(make({{"parameters", std::string("x=1")}})) == "parameters");
  CHECK(blamed([] { velocityFields().make("meristem", {{"axis", std::vector<double>{0, 0, 0}}}); }) == "axis");
  CHECK(blamed([] { velocityFields().make("bump", {{"h", -1.0}}); }) == "h");
  CHECK_THROWS_WITH(parseExpressionParameters("r=1, s"), Contains("expected name=value items") && Contains("'s'"));
  CHECK_THROWS_WITH(parseExpressionParameters("r=1, r=2"), Contains("'r' is given twice"));
  CHECK(parseExpressionParameters(" a = 1, b=2.5 ,") == std::map<std::string, double>{{"a", 1.0}, {"b", 2.5}});
}

TEST_CASE("the threshold and surface tables", "[growth][registries]") {
  CHECK(divisionThresholds().names() == std::vector<std::string>{"fixed", "property", "noisy"});
  CHECK(divisionThresholds().make("fixed", {{"size", 2.0}}).kind() == SizeThreshold::Kind::Fixed);
  CHECK(divisionThresholds().make("property", {}).kind() == SizeThreshold::Kind::Property);
  CHECK(divisionThresholds().make("noisy", {{"mean", 2.0}}).kind() == SizeThreshold::Kind::Noisy);

  CHECK(surfaces().names() == std::vector<std::string>{"sphere", "paraboloid", "dome"});
  const SurfaceProjection none;
  const SurfaceProjection sphere = surfaces().make("sphere", {{"radius", 2.0}}, none);
  CHECK(sphere(Vec3(0, 0, 5)).isApprox(Vec3(0, 0, 2)));
  const SurfaceProjection paraboloid = surfaces().make("paraboloid", {}, none);
  CHECK(paraboloid(Vec3(0, 0, 1)).isApprox(Vec3(0, 0, 0)));
  CHECK_THROWS_WITH(surfaces().make("dome", {}, none), Contains("'dome' needs"));
  const SurfaceProjection own = [](const Vec3& x) { return Vec3(x.x(), x.y(), 7.0); };
  CHECK(surfaces().make("dome", {}, own)(Vec3(1, 2, 3)) == Vec3(1, 2, 7));
}

TEST_CASE("the integrator's enums have one name table each", "[growth][registries]") {
  CHECK(integrationSchemes().names() == std::vector<std::string>{"euler", "heun"});
  for (const auto& e : integrationSchemes().entries()) CHECK(schemeName(e.value) == e.name);
  CHECK(parseScheme("heun") == IntegrationScheme::Heun);
  CHECK(parseScheme("rk2") == IntegrationScheme::Heun);  // an alias, not a choice
  CHECK_THROWS_WITH(parseScheme("rk4"), Contains("unknown integration scheme 'rk4'") && Contains("euler, heun"));
  CHECK(velocitySources().names() == std::vector<std::string>{"field", "boundary"});
  CHECK(velocitySources().parse("boundary") == VelocitySource::HarmonicFromControl);
  CHECK_THROWS_AS(velocitySources().parse("control"), InputError);
}
