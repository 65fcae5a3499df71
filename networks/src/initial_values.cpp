// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/initial_values.hpp"

#include <muParser.h>

#include <cmath>
#include <memory>

#include "tessella/tissue/errors.hpp"

namespace tessella::networks {

namespace {
struct InitialParser {
  mu::Parser parser;
  double x = 0, y = 0, z = 0, measure = 0;
  std::vector<double> params;

  InitialParser(const std::string& expression, const std::map<std::string, double>& parameters) {
    for (const auto& [name, value] : parameters) params.push_back(value);
    try {
      std::size_t k = 0;
      for (const auto& [name, value] : parameters) parser.DefineVar(name, &params[k++]);
      parser.DefineVar("x", &x);
      parser.DefineVar("y", &y);
      parser.DefineVar("z", &z);
      parser.DefineVar("measure", &measure);
      parser.SetExpr(expression);
      parser.Eval();
    } catch (const mu::Parser::exception_type& e) {
      throw InputError("initial value \"" + expression + "\": " + e.GetMsg() + " (at position " +
                       std::to_string(e.GetPos()) + "; the variables are x, y, z, measure and the parameters)");
    }
  }
};
}  // namespace

void checkInitialExpression(const std::string& expression, const std::map<std::string, double>& parameters) {
  InitialParser p(expression, parameters);
}

std::vector<double> initialConcentrations(const std::string& expression, const NetworkGraph& graph,
                                          const std::map<std::string, double>& parameters, double noise,
                                          std::mt19937_64& rng) {
  if (!(std::isfinite(noise) && noise >= 0.0))
    throw InputError("initial value noise " + std::to_string(noise) + " must be finite and >= 0");
  auto p = std::make_unique<InitialParser>(expression, parameters);
  std::uniform_real_distribution<double> uniform(0.0, noise);
  std::vector<double> out(graph.numCells());
  for (std::size_t c = 0; c < out.size(); ++c) {
    p->x = graph.centroid[c].x();
    p->y = graph.centroid[c].y();
    p->z = graph.centroid[c].z();
    p->measure = graph.measure[c];
    const double v = p->parser.Eval();
    if (!std::isfinite(v))
      throw InputError("initial value \"" + expression + "\" gave " + std::to_string(v) + " in cell " +
                       std::to_string(c));
    out[c] = v + (noise > 0 ? uniform(rng) : 0.0);
  }
  return out;
}

}  // namespace tessella::networks
