// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "reaction_terms.hpp"

#include <muParser.h>

#include <cmath>
#include <sstream>

namespace tessella::sim::detail {

ReactionTerms::ReactionTerms(const std::vector<std::string>& names, const std::vector<std::string>& expressions,
                             const std::vector<std::string>& keys)
    : names_(names), expressions_(expressions), keys_(keys), values_(names.size(), 0.0) {
  for (std::size_t s = 0; s < expressions.size(); ++s) {
    if (expressions[s].empty()) continue;
    auto parser = std::make_unique<mu::Parser>();
    try {
      for (std::size_t v = 0; v < names.size(); ++v) parser->DefineVar(names[v], &values_[v]);
      parser->SetExpr(expressions[s]);
      parser->Eval();  // forces the parse: syntax errors and unknown names surface here
    } catch (const mu::Parser::exception_type& e) {
      const std::string token = e.GetToken().empty() ? "" : " (near '" + e.GetToken() + "'";
      throw ReactionExpressionError(
          s, "\"" + expressions[s] + "\": " + e.GetMsg() +
                 (token.empty() ? " (" : token + ", ") + "at position " + std::to_string(e.GetPos()) +
                 "); the variables are the species names");
    }
    parsers_.push_back(std::move(parser));
    target_.push_back(s);
  }
}

ReactionTerms::~ReactionTerms() = default;

void ReactionTerms::evaluate(std::span<const double> u, std::span<double> rate) {
  for (std::size_t v = 0; v < values_.size(); ++v) values_[v] = u[v];
  for (std::size_t k = 0; k < parsers_.size(); ++k) {
    const double r = parsers_[k]->Eval();
    if (!std::isfinite(r)) {
      const std::size_t s = target_[k];
      std::ostringstream msg;
      msg << (s < keys_.size() ? keys_[s] : names_[s]) << ": \"" << expressions_[s] << "\" gave " << r << " at";
      for (std::size_t v = 0; v < names_.size(); ++v) msg << (v ? ", " : " ") << names_[v] << " = " << values_[v];
      throw InputError(msg.str());
    }
    rate[target_[k]] = r;
  }
}

}  // namespace tessella::sim::detail
