// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// BatchExpression: a muparser expression's bytecode (after muparser's own
// parsing, constant folding and optimisation) run over a block of cells at
// once: each instruction on all the block's cells before the next, so the
// interpretation is paid once per block instead of once per cell and the
// arithmetic runs in loops the compiler vectorises. Every instruction does for
// one cell what muparser's interpreter (ParserBase::ParseCmdCodeBulk) does, in
// the same order, so a cell's value is bit-identical to Parser::Eval, with one
// difference: a base raised to the constant 2, 3 or 4 is multiplied out (x * x,
// x * x * x, x * x * x * x), as muparser itself does when the base is a
// variable (`a^2` is a * a) but not for other bases (`(a / K)^2` calls pow,
// whose result is not always the correctly rounded square). Both branches of
// `c ? u : v` are evaluated and each cell keeps its own. Not thread-safe (one
// work space per object).

#include <cstddef>
#include <span>
#include <vector>

#include <muParserBase.h>

namespace tessella::networks::detail {

class BatchExpression {
 public:
  /// The most cells evaluate() takes at once.
  static constexpr std::size_t kBlock = 128;
  /// A variable's values: cell k's is base[k * stride] (stride 0: one value for every cell).
  struct Column {
    const double* base = nullptr;
    std::size_t stride = 0;
  };
  /// Compiles `parser`'s bytecode (the parser must have parsed its expression: one Eval() done);
  /// `variables` are the addresses its variables were defined at, a variable's column is its index there.
  /// supported() is false when the bytecode holds what this does not run (a variable not listed, string or
  /// bulk functions, functions without arguments, assignments); the caller then evaluates cell by cell.
  BatchExpression(const mu::ParserBase& parser, std::span<double* const> variables);

  bool supported() const { return supported_; }
  /// out[k] = the expression's value at cell first + k, for k < count <= kBlock.
  void evaluate(std::span<const Column> columns, std::size_t first, std::size_t count, double* out) const;

 private:
  enum class Op {
    Le, Ge, Neq, Eq, Lt, Gt, Add, Sub, Mul, Div, Pow, And, Or,  // binary: the two top values, one result
    Var, Val, VarPow2, VarPow3, VarPow4, VarMul,                 // push
    Pow2, Pow3, Pow4,                                            // the top value to a constant power
    Function, MultiFunction,                                     // argc arguments, one result
    If, Else, EndIf
  };
  struct Instruction {
    Op op;
    int argc = 0;
    std::size_t column = 0;
    double data = 0, data2 = 0;  // Val: data2; VarMul: x * data + data2 (muparser's fields)
    mu::generic_callable_type function{};
  };
  std::vector<Instruction> code_;
  std::size_t depth_ = 0, branches_ = 0, result_ = 0;
  bool supported_ = true;
  mutable std::vector<double> stack_, saved_, conditions_;  // depth_, branches_ and branches_ blocks
};

}  // namespace tessella::networks::detail
