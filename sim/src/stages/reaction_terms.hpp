// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// ReactionTerms: the reaction rates of the diffusion section's species,
// muparser expressions in the species names ("A: -k*A" is written
// "-0.5*A"), compiled once to muparser bytecode and evaluated at each node
// (DiffusionReaction::setReaction). Not thread-safe: the solver calls it
// serially, and each DiffusionStage owns its own instance.

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tessella/tissue/errors.hpp"

namespace mu {
class Parser;
}

namespace tessella::sim::detail {

/// A reaction expression that does not compile: which species' expression,
/// and muparser's message with the token and position.
class ReactionExpressionError : public InputError {
 public:
  ReactionExpressionError(std::size_t species, const std::string& message)
      : InputError(message), species_(species) {}
  std::size_t species() const { return species_; }

 private:
  std::size_t species_;
};

class ReactionTerms {
 public:
  /// `names` are the species in solver order, `expressions` their rates
  /// (same size; "" for a species without a reaction), `keys` the config
  /// keys they came from (named when a rate is not finite). Every expression
  /// is parsed here: a syntax error or a name that is not a species is a
  /// ReactionExpressionError.
  ReactionTerms(const std::vector<std::string>& names, const std::vector<std::string>& expressions,
                const std::vector<std::string>& keys);
  ~ReactionTerms();
  ReactionTerms(const ReactionTerms&) = delete;
  ReactionTerms& operator=(const ReactionTerms&) = delete;

  /// The rates at one node from the values of all species there (the
  /// signature of tessella::solvers::ReactionFunction). A rate that is not finite
  /// (1/h at h = 0) is an InputError naming the key and the values.
  void evaluate(std::span<const double> u, std::span<double> rate);

 private:
  std::vector<std::string> names_, expressions_, keys_;
  std::vector<double> values_;  // the variables the parsers read (fixed addresses)
  std::vector<std::unique_ptr<mu::Parser>> parsers_;
  std::vector<std::size_t> target_;  // species each parser gives the rate of
};

}  // namespace tessella::sim::detail
