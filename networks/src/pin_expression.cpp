// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/pin_expression.hpp"

#include <muParser.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::networks {

PinExpression::PinExpression(const NetworkModel& model)
    : expression_(model.pin.expression),
      params_(model.parameters.size(), 0.0),
      parser_(std::make_unique<mu::Parser>()) {
  std::size_t p = 0;
  for (const auto& [name, value] : model.parameters) params_[p++] = value;
  const auto& names = pinExpressionVariables();
  try {
    for (std::size_t v = 0; v < names.size(); ++v) parser_->DefineVar(names[v], &values_[v]);
    std::size_t k = 0;
    for (const auto& [name, value] : model.parameters) parser_->DefineVar(name, &params_[k++]);
    parser_->DefineVar("t", &t_);
    parser_->SetExpr(expression_);
    parser_->Eval();  // forces the parse: syntax errors and unknown names surface here
    const auto used = parser_->GetUsedVar();
    for (std::size_t v = 0; v < names.size(); ++v) used_[v] = used.count(names[v]) > 0;
  } catch (const mu::Parser::exception_type& e) {
    const std::string token = e.GetToken().empty() ? "" : "near '" + e.GetToken() + "', ";
    throw InputError(
        "network: PIN expression \"" + expression_ + "\": " + e.GetMsg() + " (" + token +
        "at position " + std::to_string(e.GetPos()) +
        "; the variables are c_i, c_j, pin, pin_opposite, flux, wall, measure, pin_cell, t and the "
        "parameters)");
  }
}

PinExpression::~PinExpression() = default;

double PinExpression::evaluate(double t, const Arguments& a, std::size_t cell,
                               std::size_t neighbour) {
  values_ = a;
  t_ = t;
  const double r = parser_->Eval();
  if (!std::isfinite(r)) {
    std::ostringstream msg;
    msg << "network: PIN expression \"" << expression_ << "\" gave " << r << " on cell " << cell
        << "'s side of its interface with cell " << neighbour << " at t = " << formatNumber(t)
        << " with";
    const auto& names = pinExpressionVariables();
    for (std::size_t v = 0; v < names.size(); ++v)
      msg << (v ? ", " : " ") << names[v] << " = " << formatNumber(a[v]);
    throw InputError(msg.str());
  }
  return r;
}

PinExpression::Arguments PinExpression::derivatives(double t, const Arguments& a, std::size_t cell,
                                                    std::size_t neighbour) {
  Arguments d{};
  const double root = std::cbrt(std::numeric_limits<double>::epsilon());
  for (std::size_t v = 0; v < a.size(); ++v) {
    if (!used_[v] || v == kWall || v == kMeasure) continue;
    const double h = root * std::max(std::abs(a[v]), 1.0);
    Arguments b = a;
    b[v] = a[v] + h;
    const double up = evaluate(t, b, cell, neighbour);
    b[v] = a[v] - h;
    const double down = evaluate(t, b, cell, neighbour);
    d[v] = (up - down) / (2 * h);
  }
  return d;
}

}  // namespace tessella::networks
