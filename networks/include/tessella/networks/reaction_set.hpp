// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// ReactionSet: the reactions of a NetworkModel compiled once to muparser
// bytecode and evaluated cell by cell. Variables: the species (the cell's
// concentrations), the model's parameters, `measure`, `x`, `y`, `z` (the
// cell's centroid), `t`, the cell properties the model names, and per species
// s the neighbourhood terms `sum_<s>` (sum over the cell's neighbours j of
// L_ij c_j,s) and `mean_<s>` (the same divided by sum_j L_ij). Not
// thread-safe (the variables are members).

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tessella/networks/network_model.hpp"
#include "tessella/tissue/vec3.hpp"

namespace mu {
class Parser;
}

namespace tessella::networks {

class ReactionSet {
 public:
  /// Parses every reaction: a syntax error or an unknown name is an
  /// InputError naming the species, the expression and muparser's message.
  explicit ReactionSet(const NetworkModel& model);
  ~ReactionSet();
  ReactionSet(const ReactionSet&) = delete;
  ReactionSet& operator=(const ReactionSet&) = delete;

  bool empty() const { return parsers_.empty(); }
  /// Some reaction reads sum_<s> or mean_<s> of species s.
  bool usesNeighbourhood(std::size_t s) const { return uses_sum_[s] || uses_mean_[s]; }
  bool usesAnyNeighbourhood() const;
  /// Sets the cell's values (concentrations `conc`, one per species; its
  /// properties in model.cell_properties order; `neighbourhood`: sum_<s> of
  /// every species then mean_<s> of every species, or empty for zeros), then
  /// the rates of all species into `rate` (0 for a species without a
  /// reaction). A rate that is not finite is an InputError naming the
  /// species, `cell` and the values.
  void evaluate(double t, std::size_t cell, double measure, const Vec3& centroid, std::span<const double> properties,
                std::span<const double> conc, std::span<double> rate, std::span<const double> neighbourhood = {});

  // One reaction at a time (what evaluate() does in parts): set() the cell's values, change single
  // concentrations or neighbourhood terms, and evaluate the reaction of one species.
  /// Whether the reaction of species s reads the concentration of species q.
  bool reads(std::size_t s, std::size_t q) const { return reads_[s * species_.size() + q] != 0; }
  /// Whether the reaction of species s reads sum_<q> (which 0) or mean_<q> (which 1).
  bool readsNeighbourhood(std::size_t s, std::size_t which, std::size_t q) const {
    return reads_neighbourhood_[(s * 2 + which) * species_.size() + q] != 0;
  }
  /// Sets the cell's values as evaluate() does, without evaluating.
  void set(double t, double measure, const Vec3& centroid, std::span<const double> properties,
           std::span<const double> conc, std::span<const double> neighbourhood = {});
  void setConcentration(std::size_t q, double c) { conc_[q] = c; }
  /// sum_<q> (which 0) or mean_<q> (which 1).
  void setNeighbourhood(std::size_t which, std::size_t q, double v) { neighbourhood_[which * species_.size() + q] = v; }
  /// The rate of species s at the values set (0 without a reaction); not finite: the InputError of evaluate().
  double rate(std::size_t s, std::size_t cell) const;

 private:
  std::vector<std::string> species_, expressions_, properties_;
  std::vector<double> conc_, props_, neighbourhood_;
  std::vector<bool> uses_sum_, uses_mean_;
  std::vector<char> reads_, reads_neighbourhood_;  // per species s: reads(s, q), readsNeighbourhood(s, which, q)
  std::vector<int> parser_of_;                     // per species: its parser, -1 without a reaction
  [[noreturn]] void notFinite(std::size_t s, std::size_t cell, double r) const;
  double t_ = 0, measure_ = 0, x_ = 0, y_ = 0, z_ = 0;
  std::vector<std::unique_ptr<mu::Parser>> parsers_;
  std::vector<std::size_t> target_;
};

}  // namespace tessella::networks
