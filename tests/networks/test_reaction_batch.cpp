// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// ReactionSet::evaluateCells (each reaction's bytecode run over blocks of cells) against muparser's own
// interpreter, cell by cell, bit for bit.
#include <catch2/catch.hpp>

#include <muParser.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "network_fixtures.hpp"
#include "tessella/networks/network_system.hpp"
#include "tessella/networks/reaction_set.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using namespace tessella::networks;

namespace {

// Cells with random values (some of them exactly 0, 1 or 2, where comparisons and conditions turn), `n` of them.
struct Cells {
  std::size_t n = 0, S = 3;
  std::vector<double> conc, neighbourhood, measure, prop;
  std::vector<Vec3> centroid;
  CellValues values(double t) const {
    CellValues v;
    v.t = t;
    v.conc = conc.data();
    v.neighbourhood = neighbourhood.data();
    v.measure = measure.data();
    v.centroid = centroid.data();
    v.properties = {prop.data()};
    return v;
  }
};

Cells randomCells(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::uniform_int_distribution<int> pick(0, 9);
  auto value = [&] {
    const int k = pick(rng);
    return k == 0 ? 0.0 : k == 1 ? 1.0 : k == 2 ? 2.0 : u(rng);
  };
  Cells c;
  c.n = n;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t s = 0; s < 3; ++s) c.conc.push_back(value());
    for (std::size_t s = 0; s < 6; ++s) c.neighbourhood.push_back(value());
    c.measure.push_back(0.5 + std::abs(u(rng)));
    c.prop.push_back(value());
    c.centroid.emplace_back(u(rng), u(rng), u(rng));
  }
  return c;
}

// muparser's value of `expression` at cell i, with the ReactionSet's variables and the parameters as constants.
double muparserValue(const std::string& expression, const Cells& c, std::size_t i, double t,
                     const std::vector<std::pair<std::string, double>>& parameters) {
  mu::Parser p;
  const char* names[] = {"a", "b", "h"};
  double conc[3], nb[6], prop = c.prop[i], measure = c.measure[i];
  double x = c.centroid[i].x(), y = c.centroid[i].y(), z = c.centroid[i].z(), time = t;
  for (std::size_t s = 0; s < 3; ++s) {
    conc[s] = c.conc[i * 3 + s];
    nb[s] = c.neighbourhood[i * 6 + s];
    nb[3 + s] = c.neighbourhood[i * 6 + 3 + s];
    p.DefineVar(names[s], &conc[s]);
    p.DefineVar(std::string("sum_") + names[s], &nb[s]);
    p.DefineVar(std::string("mean_") + names[s], &nb[3 + s]);
  }
  for (const auto& [name, value] : parameters) p.DefineConst(name, value);
  p.DefineVar("zone", &prop);
  p.DefineVar("measure", &measure);
  p.DefineVar("x", &x);
  p.DefineVar("y", &y);
  p.DefineVar("z", &z);
  p.DefineVar("t", &time);
  p.SetExpr(expression);
  return p.Eval();
}

bool sameBits(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

}  // namespace

TEST_CASE("Reactions over blocks of cells give muparser's values bit for bit", "[networks]") {
  const std::vector<std::pair<std::string, double>> parameters = {{"k", 1.7}, {"K", 0.3}, {"n", 2.5}};
  // Every kind of muparser instruction: variables and constants (folded or not), the optimised forms
  // (2 * a + 1, a^2, a^3, a^4), every binary operator, unary minus, functions of one, two and any number of
  // arguments, nested conditions, neighbourhood terms, properties, measure, centroid and time.
  const std::vector<std::string> expressions = {
      "k * a - K * b + 2 * h + 1",
      "a^2 + b^3 - h^4 + a * a + k^2",
      "a^n + abs(b)^1.5 - a^0.5 + a^(-2) + a^1 + a^0",
      "-a + (-b) * -h / (1 + a * a) - sum_a + mean_b * measure",
      "a < b ? (h <= 1 ? a : b) : (h >= 2 ? -h : zone > 0 ? x : y)",
      "(a == b) + (a != 0) + (a > h) + (a < 1 && b > 0) + (a > 1 || h < 0) + (zone == 2)",
      "sin(a) + cos(b) + exp(h / 3) + log(abs(a) + 1) + sqrt(abs(b)) + tanh(h) + sign(a) + rint(b) + abs(h)",
      "min(a, b) + max(a, b, h) + sum(a, b, h, 1) + avg(a, 2, x) + atan2(a, b)",
      "z * t + x - y + sum_h * mean_h - mean_a / (1 + sum_b^2)",
      "1 / a + a / 0 + 0 * (b > 1 ? 1 / 0 : 0)",
      "3",
      "h",
      "2 * h + 1",
      "h = a * k",  // an assignment: left to muparser, cell by cell
  };
  const Cells cells = randomCells(700, 3);  // several blocks, the last one short
  for (const std::string& e : expressions) {
    INFO(e);
    NetworkModel m;
    m.species = {{"a", e, 0.0}, {"b", "", 0.0}, {"h", "k", 0.0}};
    m.parameters = {parameters.begin(), parameters.end()};
    m.cell_properties = {"zone"};
    ReactionSet set(m);
    std::vector<double> rate(cells.n * 3, -1.0);
    const std::size_t first = 5, count = cells.n - 5;
    try {
      set.evaluateCells(cells.values(0.75), first, count, rate.data());
    } catch (const InputError&) {
      // A value that is not finite (every cell's rates are written before the check).
    }
    std::size_t differ = 0;
    for (std::size_t i = first; i < cells.n; ++i) {
      if (!sameBits(rate[i * 3], muparserValue(e, cells, i, 0.75, parameters))) ++differ;
      CHECK(rate[i * 3 + 1] == 0.0);
      CHECK(rate[i * 3 + 2] == 1.7);
    }
    CHECK(differ == 0);
    CHECK(rate[0] == -1.0);  // cells before `first` untouched
  }
}

TEST_CASE("A constant exponent 2, 3 or 4 multiplies out, whatever the base", "[networks]") {
  // muparser multiplies a variable's square (a^2 = a * a) but calls pow for (a / K)^2, whose result is not
  // always the correctly rounded square; the reactions multiply both.
  NetworkModel m;
  m.species = {{"a", "(a / K)^2 + 0 * b", 0.0}, {"b", "(a + b)^3", 0.0}, {"h", "(a - h)^4", 0.0}};
  m.parameters = {{"K", 0.3}};
  m.cell_properties = {"zone"};
  ReactionSet set(m);
  const Cells cells = randomCells(1000, 5);
  std::vector<double> rate(cells.n * 3);
  set.evaluateCells(cells.values(0.0), 0, cells.n, rate.data());
  for (std::size_t i = 0; i < cells.n; ++i) {
    const double a = cells.conc[i * 3], b = cells.conc[i * 3 + 1], h = cells.conc[i * 3 + 2];
    const double q = a / 0.3, s = a + b, d = a - h;
    CHECK(rate[i * 3] == q * q + 0 * b);
    CHECK(rate[i * 3 + 1] == s * s * s);
    CHECK(rate[i * 3 + 2] == d * d * d * d);
  }
}

TEST_CASE("Reactions of one cell and of blocks of cells agree bit for bit", "[networks]") {
  NetworkModel m;
  m.species = {{"a", "k * a^2 / (K^2 + a^2) - (b / K)^2 + mean_h * zone", 0.0},
               {"b", "a > 1 ? k * x : -b * t", 0.0},
               {"h", "", 0.0}};
  m.parameters = {{"k", 1.3}, {"K", 0.7}};
  m.cell_properties = {"zone"};
  ReactionSet blocks(m), single(m);
  const Cells cells = randomCells(600, 9);
  std::vector<double> rate(cells.n * 3);
  blocks.evaluateCells(cells.values(1.25), 0, cells.n, rate.data());
  for (std::size_t i = 0; i < cells.n; ++i) {
    std::vector<double> one(3);
    single.evaluate(1.25, i, cells.measure[i], cells.centroid[i], std::vector<double>{cells.prop[i]},
                    std::span<const double>(&cells.conc[i * 3], 3), one,
                    std::span<const double>(&cells.neighbourhood[i * 6], 6));
    for (std::size_t s = 0; s < 3; ++s) CHECK(rate[i * 3 + s] == one[s]);
    single.set(1.25, cells.measure[i], cells.centroid[i], std::vector<double>{cells.prop[i]},
               std::span<const double>(&cells.conc[i * 3], 3), std::span<const double>(&cells.neighbourhood[i * 6], 6));
    CHECK(single.rate(0, i) == one[0]);
    CHECK(single.rate(1, i) == one[1]);
  }
}

TEST_CASE("A rate that is not finite names the lowest such cell, also over blocks and threads", "[networks]") {
  // 5000 cells on a chain (blocks of cells on two threads); a = 2 makes the reaction divide by zero, in
  // cells 3000 and 4700.
  const std::size_t n = 5000;
  NetworkModel m = testing::oneSpecies("a", 0.0, "1 / (a - 2)");
  const NetworkGraph g = testing::chainGraph(std::vector<double>(n, 1.0), std::vector<double>(n - 1, 1.0));
  for (std::size_t threads : {1, 2}) {
    NetworkSystem system(m, g);
    system.setThreads(threads);
    std::vector<double> y(n, 1.0), f(n);
    y[4700] = 2.0;
    y[3000] = 2.0;
    try {
      system.rhs(0.5, y, f);
      FAIL("no error");
    } catch (const InputError& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find("reaction of species 'a', \"1 / (a - 2)\"") != std::string::npos);
      CHECK(what.find("in cell 3000 at t = 0.5 with a = 2") != std::string::npos);
    }
  }
}
