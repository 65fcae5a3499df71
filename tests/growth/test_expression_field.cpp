// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <omp.h>

#include <random>
#include <string>
#include <vector>

#include "tessella/growth/bump_field.hpp"
#include "tessella/growth/expression_field.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using namespace tessella::growth;
using Catch::Matchers::Contains;

namespace {
std::vector<Vec3> randomPoints(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<Vec3> x(n);
  for (auto& p : x) p = Vec3(u(rng), u(rng), u(rng));
  return x;
}
}  // namespace

TEST_CASE("an expression field equals the built-in field it spells out", "[growth][expression]") {
  const ExpressionField e(ExpressionFieldParams{
      .vx = "0",
      .vy = "a*(1 + b*t*x^2/(h + b*t)^2)*exp(-x^2/(h + b*t))",
      .vz = "0",
      .parameters = {{"a", 0.7}, {"b", 0.4}, {"h", 1.5}}});
  const BumpField bump(BumpFieldParams{.a = 0.7, .b = 0.4, .h = 1.5});
  const auto x = randomPoints(5000, 1);
  std::vector<Vec3> out(x.size());
  for (double t : {0.0, 1.25}) {
    e.velocities(x, t, out);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3 ref = bump.velocity(x[i], t);
      REQUIRE((out[i] - ref).norm() <= 1e-12 * (1 + ref.norm()));
      if (i % 500 == 0) CHECK((e.velocity(x[i], t) - ref).norm() <= 1e-12 * (1 + ref.norm()));
    }
  }
}

TEST_CASE("bulk evaluation is the same with one and two threads", "[growth][expression]") {
  const ExpressionField e(ExpressionFieldParams{
      .vx = "r*x + s*y*z", .vy = "r*y - sin(t*x)", .vz = "t", .parameters = {{"r", 0.2}, {"s", -1}}});
  const LinearField lin = uniformExpansion(0.2);
  const auto x = randomPoints(10007, 2);  // not a multiple of the thread count
  std::vector<Vec3> one(x.size()), two(x.size());
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  e.velocities(x, 0.5, one);
  omp_set_num_threads(2);
  e.velocities(x, 0.5, two);
  omp_set_num_threads(saved);
  for (std::size_t i = 0; i < x.size(); ++i) {
    REQUIRE(one[i] == two[i]);
    const Vec3 expect(0.2 * x[i].x() - x[i].y() * x[i].z(), 0.2 * x[i].y() - std::sin(0.5 * x[i].x()),
                      0.5);
    REQUIRE((one[i] - expect).norm() <= 1e-12 * (1 + expect.norm()));
  }
}

TEST_CASE("bad expressions are InputErrors quoting the expression and position",
          "[growth][expression]") {
  SECTION("syntax error") {
    try {
      ExpressionField e(ExpressionFieldParams{.vx = "x +* 2"});
      FAIL("no error");
    } catch (const InputError& err) {
      CHECK_THAT(err.what(), Contains("vx") && Contains("x +* 2") && Contains("position"));
    }
  }
  SECTION("unknown name") {
    try {
      ExpressionField e(ExpressionFieldParams{.vy = "k*y"});
      FAIL("no error");
    } catch (const InputError& err) {
      CHECK_THAT(err.what(), Contains("vy") && Contains("k*y") && Contains("k"));
    }
  }
  SECTION("unbalanced parenthesis") {
    CHECK_THROWS_WITH(ExpressionField(ExpressionFieldParams{.vz = "(x+1"}), Contains("(x+1"));
  }
  SECTION("a parameter may not shadow a variable") {
    CHECK_THROWS_WITH(ExpressionField(ExpressionFieldParams{.parameters = {{"t", 1.0}}}),
                      Contains("'t'"));
  }
}
