// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Stochastic shortest-wall rule of Besson and Dumais (2011): the candidate
// walls are the local minima of the new wall's measure over planes through
// the centroid, and candidate i is chosen with probability
//   p_i = exp(-beta L_i / L_min) / sum_j exp(-beta L_j / L_min),
// L the length (2D) or area (3D), L_min the shortest candidate's. Large beta
// tends to Errera's deterministic rule. (Besson and Dumais scale lengths by
// the cell's size rather than L_min; dividing by L_min makes beta
// dimensionless and independent of cell shape.)

#include "tessella/growth/division_rule.hpp"
#include "tessella/growth/shortest_wall_search.hpp"

namespace tessella::growth {

class BessonDumaisRule final : public DivisionRule {
 public:
  /// beta >= 0 and finite (InputError naming the value otherwise).
  explicit BessonDumaisRule(double beta = 10.0, ShortestWallSearchOptions options = {});
  Plane plane(const Tissue& t, CellId c, Rng& rng) const override;
  std::string name() const override { return "besson_dumais"; }
  /// The candidates and their probabilities for a cell (for analyses and tests).
  std::vector<std::pair<WallCandidate, double>> candidates(const Tissue& t, CellId c) const;
  double beta() const { return beta_; }

 private:
  std::vector<std::pair<WallCandidate, double>> candidates(const NewWallMeasure& m) const;
  double beta_;
  ShortestWallSearchOptions options_;
};

}  // namespace tessella::growth
