// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/besson_dumais_rule.hpp"

#include <cmath>

#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::growth {

BessonDumaisRule::BessonDumaisRule(double beta, ShortestWallSearchOptions options)
    : beta_(beta), options_(options) {
  if (!(beta >= 0) || !std::isfinite(beta))
    throw InputError("besson_dumais rule: beta = " + formatNumber(beta) +
                     " must be finite and >= 0");
}

std::vector<std::pair<WallCandidate, double>> BessonDumaisRule::candidates(const Tissue& t,
                                                                           CellId c) const {
  return candidates(NewWallMeasure(t, c));
}

std::vector<std::pair<WallCandidate, double>> BessonDumaisRule::candidates(const NewWallMeasure& m) const {
  const std::vector<WallCandidate> minima = newWallLocalMinima(m, options_);
  const double shortest = minima.front().measure;
  std::vector<std::pair<WallCandidate, double>> out;
  double total = 0;
  for (const WallCandidate& w : minima) {
    // exp(-beta L / Lmin) scaled by exp(beta): the same ratios, no underflow.
    const double weight = shortest > 0 ? std::exp(-beta_ * (w.measure / shortest - 1.0)) : 1.0;
    out.emplace_back(w, weight);
    total += weight;
  }
  for (auto& [w, p] : out) p /= total;
  return out;
}

Plane BessonDumaisRule::plane(const Tissue& t, CellId c, Rng& rng) const {
  const NewWallMeasure m(t, c);  // gathered once: candidates and plane point
  const auto cands = candidates(m);
  const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  double acc = 0;
  const Vec3& point = m.point();
  for (const auto& [w, p] : cands) {
    acc += p;
    if (u < acc) return Plane{point, w.normal};
  }
  return Plane{point, cands.back().first.normal};
}

DivisionRuleEntry bessonDumaisRuleEntry() {
  return {"besson_dumais", "The stochastic shortest wall of Besson and Dumais: a random choice among the local minima "
                           "of the new wall's length.",
          {ParamSpec("beta", ParamType::Float,
                     "Besson-Dumais selectivity: candidate walls are chosen with probability ~ exp(-beta L / L_min).")
               .byDefault(10.0)
               .atLeast(0)},
          [](const ParamValues& p) {
            return blameParam("beta", [&] { return std::make_shared<const BessonDumaisRule>(p.getFloat("beta")); });
          }};
}

}  // namespace tessella::growth
