// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// ReactionSet: the reactions of a NetworkModel compiled once to muparser
// bytecode and evaluated for one cell or for many cells at once (each
// reaction's bytecode run over blocks of cells: evaluateCells). Variables: the
// species (the cell's concentrations), the model's parameters, `measure`, `x`,
// `y`, `z` (the cell's centroid), `t`, the cell properties the model names,
// and per species s the neighbourhood terms `sum_<s>` (sum over the cell's
// neighbours j of L_ij c_j,s) and `mean_<s>` (the same divided by sum_j L_ij).
// A cell's rates are the same bit for bit whichever way they are evaluated;
// they are muparser's, except that a constant exponent 2, 3 or 4 multiplies
// (`(A / K)^2` is (A / K) * (A / K), as muparser does for a variable, `A^2`).
// Not thread-safe (the variables and work space are members).

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

namespace detail {
class BatchExpression;
}

/// Many cells' values for ReactionSet::evaluateCells, cell c's at index c: concentrations conc[c S + s]
/// (S species), neighbourhood terms neighbourhood[c 2 S + v] (sum_<s> then mean_<s>; null: zeros),
/// measure[c], centroid[c], and per cell property of the model (in model.cell_properties order)
/// properties[k][c].
struct CellValues {
  double t = 0;
  const double* conc = nullptr;
  const double* neighbourhood = nullptr;
  const double* measure = nullptr;
  const Vec3* centroid = nullptr;
  std::vector<const double*> properties;
};

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
  /// The rates of all species of the cells first .. first + count - 1 into rate[c S + s] (0 for a species
  /// without a reaction), the same values evaluate() gives cell by cell. A rate that is not finite: the
  /// InputError of evaluate() for the lowest such cell.
  void evaluateCells(const CellValues& values, std::size_t first, std::size_t count, double* rate);

  /// The central differences of the reactions in the cells' own concentrations, cells first .. first + count - 1
  /// (cell c's values as for evaluateCells): for each species s and concentration q its reaction reads,
  /// (r_s(c_q + h) - r_s(c_q - h)) / (2 h), h = root max(|c_q|, 1), is added to value[position[c S + s] + q].
  /// The same values, bit for bit, as set(), setConcentration() and rate() give cell by cell. Returns false,
  /// having added only finite differences, when a perturbed rate is not finite (the caller repeats the cells one
  /// by one with rate() for the error).
  bool differenceCells(const CellValues& values, std::size_t first, std::size_t count, double root,
                       const std::size_t* position, double* value);
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
  // Reaction k (parsers_ order) at the values set (the batch program over the members, or muparser's Eval).
  double evaluateOne(std::size_t k) const;
  // The addresses of the variables the parsers read: the batch programs' columns, in this order.
  std::vector<double*> variables();
  void setCell(const CellValues& values, std::size_t c);  // the members from cell c's values
  // work_->columns: the columns of the cells' values in the order of variables(), cell `first` at row 0.
  void cellColumns(const CellValues& values, std::size_t first);
  double t_ = 0, measure_ = 0, x_ = 0, y_ = 0, z_ = 0;
  std::vector<std::unique_ptr<mu::Parser>> parsers_;
  std::vector<std::unique_ptr<detail::BatchExpression>> batch_;  // per parser: its bytecode over blocks of cells
  std::vector<std::size_t> target_;
  struct Workspace;  // the batch programs' columns (the members', evaluateCells') and a block of values
  std::unique_ptr<Workspace> work_;
};

}  // namespace tessella::networks
