// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "batch_expression.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace tessella::networks::detail {

namespace {
constexpr std::size_t B = BatchExpression::kBlock;

// f(a_0[k], ..., a_{N-1}[k]) into out[k] for k < count; `args` the blocks of the N arguments.
template <std::size_t N, std::size_t... I>
void callEach(const mu::generic_callable_type& f, double* const* args, double* out, std::size_t count,
              std::index_sequence<I...>) {
  for (std::size_t k = 0; k < count; ++k) out[k] = f.call_fun<N>(args[I][k]...);
}

template <std::size_t N>
void callEach(const mu::generic_callable_type& f, double* const* args, double* out, std::size_t count) {
  callEach<N>(f, args, out, count, std::make_index_sequence<N>{});
}
}  // namespace

BatchExpression::BatchExpression(const mu::ParserBase& parser, std::span<double* const> variables) {
  const mu::ParserByteCode& bytecode = parser.GetByteCode();
  const mu::SToken* token = bytecode.GetBase();
  const std::size_t size = bytecode.GetSize();
  std::size_t sp = 0, open = 0;  // the stack's depth and the open conditionals while compiling
  auto column = [&](const double* address, std::size_t& out) {
    const auto it = std::find(variables.begin(), variables.end(), address);
    if (it == variables.end()) return false;
    out = static_cast<std::size_t>(it - variables.begin());
    return true;
  };
  auto push = [&] { depth_ = std::max(depth_, ++sp); };
  for (std::size_t i = 0; i < size && token[i].Cmd != mu::cmEND; ++i) {
    const mu::SToken& t = token[i];
    Instruction in{Op::Val};
    switch (t.Cmd) {
      case mu::cmLE: in.op = Op::Le; break;
      case mu::cmGE: in.op = Op::Ge; break;
      case mu::cmNEQ: in.op = Op::Neq; break;
      case mu::cmEQ: in.op = Op::Eq; break;
      case mu::cmLT: in.op = Op::Lt; break;
      case mu::cmGT: in.op = Op::Gt; break;
      case mu::cmADD: in.op = Op::Add; break;
      case mu::cmSUB: in.op = Op::Sub; break;
      case mu::cmMUL: in.op = Op::Mul; break;
      case mu::cmDIV: in.op = Op::Div; break;
      case mu::cmPOW: in.op = Op::Pow; break;
      case mu::cmLAND: in.op = Op::And; break;
      case mu::cmLOR: in.op = Op::Or; break;
      case mu::cmVAL:
        // A constant exponent 2, 3 or 4 (the value pushed last before a power is its exponent).
        if (i + 1 < size && token[i + 1].Cmd == mu::cmPOW &&
            (t.Val.data2 == 2.0 || t.Val.data2 == 3.0 || t.Val.data2 == 4.0)) {
          in.op = t.Val.data2 == 2.0 ? Op::Pow2 : t.Val.data2 == 3.0 ? Op::Pow3 : Op::Pow4;
          ++i;
          code_.push_back(in);
          continue;
        }
        in.op = Op::Val;
        in.data2 = t.Val.data2;
        break;
      case mu::cmVAR:
      case mu::cmVARPOW2:
      case mu::cmVARPOW3:
      case mu::cmVARPOW4:
      case mu::cmVARMUL:
        if (!column(t.Val.ptr, in.column)) supported_ = false;
        in.op = t.Cmd == mu::cmVAR       ? Op::Var
                : t.Cmd == mu::cmVARPOW2 ? Op::VarPow2
                : t.Cmd == mu::cmVARPOW3 ? Op::VarPow3
                : t.Cmd == mu::cmVARPOW4 ? Op::VarPow4
                                         : Op::VarMul;
        in.data = t.Val.data;
        in.data2 = t.Val.data2;
        break;
      case mu::cmFUNC:
        // Without arguments (random numbers, say) a function is called once per cell in cell order by
        // muparser: left to it.
        if (t.Fun.argc == 0 || t.Fun.argc > 10) supported_ = false;
        in.op = t.Fun.argc > 0 ? Op::Function : Op::MultiFunction;
        in.argc = t.Fun.argc > 0 ? t.Fun.argc : -t.Fun.argc;
        in.function = t.Fun.cb;
        break;
      case mu::cmIF: in.op = Op::If; break;
      case mu::cmELSE: in.op = Op::Else; break;
      case mu::cmENDIF: in.op = Op::EndIf; break;
      default: supported_ = false;
    }
    if (!supported_) return;
    switch (in.op) {
      case Op::Var: case Op::Val: case Op::VarPow2: case Op::VarPow3: case Op::VarPow4: case Op::VarMul:
        push();
        break;
      case Op::Function:
      case Op::MultiFunction:
        if (in.argc < 1 || sp < static_cast<std::size_t>(in.argc)) supported_ = false;
        else sp -= static_cast<std::size_t>(in.argc) - 1;
        break;
      case Op::If:  // the condition leaves the stack
        if (sp < 1) supported_ = false;
        --sp;
        branches_ = std::max(branches_, ++open);
        break;
      case Op::Else:  // the first branch's value is set aside
        if (sp < 1 || open == 0) supported_ = false;
        --sp;
        break;
      case Op::EndIf:
        if (open == 0) supported_ = false;
        --open;
        break;
      default:  // binary
        if (sp < 2) supported_ = false;
        --sp;
    }
    if (!supported_) return;
    code_.push_back(in);
  }
  // muparser's result: the value at its stack index GetNumResults() (1-based).
  const int results = parser.GetNumResults();
  if (results < 1 || static_cast<std::size_t>(results) > sp || open != 0 || depth_ == 0) {
    supported_ = false;
    return;
  }
  result_ = static_cast<std::size_t>(results) - 1;
  stack_.assign(depth_ * B, 0.0);
  saved_.assign(branches_ * B, 0.0);
  conditions_.assign(branches_ * B, 0.0);
}

void BatchExpression::evaluate(std::span<const Column> columns, std::size_t first, std::size_t count,
                               double* out) const {
  std::size_t sp = 0, open = 0;
  auto slot = [&](std::size_t s) { return &stack_[s * B]; };
  auto load = [&](const Instruction& in, double* dst) {
    const Column& c = columns[in.column];
    const double* src = c.base + first * c.stride;
    if (c.stride == 1)
      std::copy(src, src + count, dst);
    else
      for (std::size_t k = 0; k < count; ++k) dst[k] = src[k * c.stride];
  };
  for (const Instruction& in : code_) {
    switch (in.op) {
      case Op::Var: load(in, slot(sp++)); continue;
      case Op::Val: std::fill(slot(sp), slot(sp) + count, in.data2); ++sp; continue;
      case Op::VarPow2: {
        double* x = slot(sp++);
        load(in, x);
        for (std::size_t k = 0; k < count; ++k) x[k] = x[k] * x[k];
        continue;
      }
      case Op::VarPow3: {
        double* x = slot(sp++);
        load(in, x);
        for (std::size_t k = 0; k < count; ++k) x[k] = x[k] * x[k] * x[k];
        continue;
      }
      case Op::VarPow4: {
        double* x = slot(sp++);
        load(in, x);
        for (std::size_t k = 0; k < count; ++k) x[k] = x[k] * x[k] * x[k] * x[k];
        continue;
      }
      case Op::VarMul: {
        double* x = slot(sp++);
        load(in, x);
        for (std::size_t k = 0; k < count; ++k) x[k] = x[k] * in.data + in.data2;
        continue;
      }
      case Op::Pow2: {
        double* x = slot(sp - 1);
        for (std::size_t k = 0; k < count; ++k) x[k] = x[k] * x[k];
        continue;
      }
      case Op::Pow3: {
        double* x = slot(sp - 1);
        for (std::size_t k = 0; k < count; ++k) x[k] = x[k] * x[k] * x[k];
        continue;
      }
      case Op::Pow4: {
        double* x = slot(sp - 1);
        for (std::size_t k = 0; k < count; ++k) x[k] = x[k] * x[k] * x[k] * x[k];
        continue;
      }
      case Op::Function: {
        const auto n = static_cast<std::size_t>(in.argc);
        sp -= n;
        std::array<double*, 10> args{};
        for (std::size_t a = 0; a < n; ++a) args[a] = slot(sp + a);
        double* r = slot(sp++);
        switch (n) {
          case 1: callEach<1>(in.function, args.data(), r, count); break;
          case 2: callEach<2>(in.function, args.data(), r, count); break;
          case 3: callEach<3>(in.function, args.data(), r, count); break;
          case 4: callEach<4>(in.function, args.data(), r, count); break;
          case 5: callEach<5>(in.function, args.data(), r, count); break;
          case 6: callEach<6>(in.function, args.data(), r, count); break;
          case 7: callEach<7>(in.function, args.data(), r, count); break;
          case 8: callEach<8>(in.function, args.data(), r, count); break;
          case 9: callEach<9>(in.function, args.data(), r, count); break;
          default: callEach<10>(in.function, args.data(), r, count);
        }
        continue;
      }
      case Op::MultiFunction: {
        const auto n = static_cast<std::size_t>(in.argc);
        sp -= n;
        std::vector<double> one(n);  // one cell's arguments, contiguous as muparser passes them
        double* r = slot(sp);
        for (std::size_t k = 0; k < count; ++k) {
          for (std::size_t a = 0; a < n; ++a) one[a] = slot(sp + a)[k];
          r[k] = in.function.call_multfun(one.data(), in.argc);
        }
        ++sp;
        continue;
      }
      case Op::If:
        --sp;
        std::copy(slot(sp), slot(sp) + count, &conditions_[open++ * B]);
        continue;
      case Op::Else:
        --sp;
        std::copy(slot(sp), slot(sp) + count, &saved_[(open - 1) * B]);
        continue;
      case Op::EndIf: {
        --open;
        const double* c = &conditions_[open * B];
        const double* yes = &saved_[open * B];
        double* x = slot(sp - 1);  // the second branch's value
        // muparser takes the second branch when the condition == 0 (NaN takes the first).
        for (std::size_t k = 0; k < count; ++k) x[k] = c[k] == 0 ? x[k] : yes[k];
        continue;
      }
      default: break;
    }
    // Binary operators: a = a op b with a the value below the top.
    --sp;
    double* a = slot(sp - 1);
    const double* b = slot(sp);
    switch (in.op) {
      case Op::Le: for (std::size_t k = 0; k < count; ++k) a[k] = a[k] <= b[k]; break;
      case Op::Ge: for (std::size_t k = 0; k < count; ++k) a[k] = a[k] >= b[k]; break;
      case Op::Neq: for (std::size_t k = 0; k < count; ++k) a[k] = a[k] != b[k]; break;
      case Op::Eq: for (std::size_t k = 0; k < count; ++k) a[k] = a[k] == b[k]; break;
      case Op::Lt: for (std::size_t k = 0; k < count; ++k) a[k] = a[k] < b[k]; break;
      case Op::Gt: for (std::size_t k = 0; k < count; ++k) a[k] = a[k] > b[k]; break;
      case Op::Add: for (std::size_t k = 0; k < count; ++k) a[k] += b[k]; break;
      case Op::Sub: for (std::size_t k = 0; k < count; ++k) a[k] -= b[k]; break;
      case Op::Mul: for (std::size_t k = 0; k < count; ++k) a[k] *= b[k]; break;
      case Op::Div: for (std::size_t k = 0; k < count; ++k) a[k] /= b[k]; break;
      case Op::Pow: for (std::size_t k = 0; k < count; ++k) a[k] = std::pow(a[k], b[k]); break;
      case Op::And: for (std::size_t k = 0; k < count; ++k) a[k] = a[k] && b[k]; break;
      case Op::Or: for (std::size_t k = 0; k < count; ++k) a[k] = a[k] || b[k]; break;
      default: break;
    }
  }
  std::copy(slot(result_), slot(result_) + count, out);
}

}  // namespace tessella::networks::detail
