// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// PinExpression: the rate of change of the PIN density on one side of an
// interface, dp_ij/dt, as a muparser expression compiled once (PIN model
// `expression`, docs/networks.md). Variables: c_i, c_j (the PIN species'
// concentration in the cell and in its neighbour), pin (p_ij), pin_opposite
// (p_ji), flux (the net flux density of the species from i into j), wall
// (the interface's measure L_ij), measure (the cell's measure V_i), pin_cell
// (the PIN amount on the cell's interfaces, sum_k L_ik p_ik), t and the
// model's parameters. Not thread-safe (the variables are members).

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "tessella/networks/network_model.hpp"

namespace mu {
class Parser;
}

namespace tessella::networks {

class PinExpression {
 public:
  /// The arguments in pinExpressionVariables() order.
  enum Argument { kCi, kCj, kPin, kPinOpposite, kFlux, kWall, kMeasure, kPinCell, kArguments };
  using Arguments = std::array<double, kArguments>;

  /// Parses model.pin.expression: a syntax error or an unknown name is an
  /// InputError naming the expression and muparser's message.
  explicit PinExpression(const NetworkModel& model);
  ~PinExpression();
  PinExpression(const PinExpression&) = delete;
  PinExpression& operator=(const PinExpression&) = delete;

  /// dp/dt on cell `cell`'s side of its interface with `neighbour`; a value
  /// that is not finite is an InputError naming the expression, the cells,
  /// the time and the arguments.
  double evaluate(double t, const Arguments& a, std::size_t cell, std::size_t neighbour);
  /// The partial derivatives with respect to each argument, by central
  /// differences (step eps^(1/3) max(|a|, 1)); 0 for an argument the
  /// expression does not use, and for wall and measure (constants).
  Arguments derivatives(double t, const Arguments& a, std::size_t cell, std::size_t neighbour);
  /// The expression reads pin_cell (its rate depends on every PIN of the cell).
  bool usesPinCell() const { return used_[kPinCell]; }

 private:
  std::string expression_;
  Arguments values_{};
  double t_ = 0;
  std::vector<double> params_;
  std::array<bool, kArguments> used_{};
  std::unique_ptr<mu::Parser> parser_;
};

}  // namespace tessella::networks
