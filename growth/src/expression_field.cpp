// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/expression_field.hpp"

#include <muParser.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "tessella/growth/parallel_threshold.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::growth {

namespace {

constexpr std::array<const char*, 3> kComponent = {"vx", "vy", "vz"};

bool reservedName(const std::string& name) {
  return name == "x" || name == "y" || name == "z" || name == "t";
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

}  // namespace

std::map<std::string, double> parseExpressionParameters(const std::string& text) {
  std::map<std::string, double> out;
  std::stringstream all(text);
  std::string item;
  while (std::getline(all, item, ',')) {
    item = trim(item);
    if (item.empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw ParamError("parameters", "expected name=value items separated by commas, got '" + item + "'");
    const std::string name = trim(item.substr(0, eq)), value = trim(item.substr(eq + 1));
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (name.empty() || used == 0 || used != value.size())
      throw ParamError("parameters", "parameter '" + item + "' is not name=number");
    if (out.count(name)) throw ParamError("parameters", "parameter '" + name + "' is given twice");
    out[name] = v;
  }
  return out;
}

// In bulk mode muparser reads every variable as an array indexed by the bulk
// position, so x, y, z and t each get a buffer of the batch size.
struct ExpressionField::Workspace {
  std::array<mu::Parser, 3> parsers;
  std::vector<double> x, y, z, t;
  std::array<std::vector<double>, 3> result;
  std::size_t capacity = 0;

  void define(std::size_t n) {
    if (n <= capacity && capacity > 0) return;
    capacity = std::max<std::size_t>(n, 1);
    for (auto* b : {&x, &y, &z, &t}) b->assign(capacity, 0.0);
    for (auto& r : result) r.assign(capacity, 0.0);
    for (auto& p : parsers) {  // redefining a variable re-links the parsed bytecode
      p.DefineVar("x", x.data());
      p.DefineVar("y", y.data());
      p.DefineVar("z", z.data());
      p.DefineVar("t", t.data());
    }
  }
};

std::unique_ptr<ExpressionField::Workspace> ExpressionField::makeWorkspace() const {
  auto ws = std::make_unique<Workspace>();
  ws->define(1);
  const std::array<const std::string*, 3> exprs = {&params_.vx, &params_.vy, &params_.vz};
  // One component after the other, so an error names the first bad one.
  for (int c = 0; c < 3; ++c) {
    mu::Parser& p = ws->parsers[c];
    try {
      for (const auto& [name, value] : params_.parameters) p.DefineConst(name, value);
      p.SetExpr(*exprs[c]);
    } catch (const mu::Parser::exception_type& e) {
      throw ParamError(kComponent[c], std::string("velocity expression ") + kComponent[c] + " = \"" + *exprs[c] +
                                          "\": " + e.GetMsg() + " (at position " + std::to_string(e.GetPos()) + ")");
    }
    try {
      p.Eval();  // forces the parse: unknown names and syntax errors surface here
    } catch (const mu::Parser::exception_type& e) {
      const std::string token = e.GetToken().empty() ? "" : " near '" + e.GetToken() + "'";
      throw ParamError(kComponent[c], std::string("velocity expression ") + kComponent[c] + " = \"" + *exprs[c] +
                                          "\": " + e.GetMsg() + token + " (at position " +
                                          std::to_string(e.GetPos()) + ")");
    }
  }
  return ws;
}

ExpressionField::ExpressionField(ExpressionFieldParams params) : params_(std::move(params)) {
  for (const auto& [name, value] : params_.parameters) {
    if (reservedName(name))
      throw ParamError("parameters", "velocity expression parameter '" + name +
                                         "' clashes with a variable (x, y, z and t are reserved)");
    if (!std::isfinite(value))
      throw ParamError("parameters", "velocity expression parameter '" + name + "' = " + formatNumber(value) +
                                         " is not finite");
  }
  workspaces_.push_back(makeWorkspace());  // parses, so errors surface at construction
}

ExpressionField::~ExpressionField() = default;

Vec3 ExpressionField::velocity(const Vec3& x, double t) const {
  std::lock_guard lock(mutex_);
  Workspace& ws = *workspaces_.front();
  ws.x[0] = x.x();
  ws.y[0] = x.y();
  ws.z[0] = x.z();
  ws.t[0] = t;
  Vec3 v;
  for (int c = 0; c < 3; ++c) v[c] = ws.parsers[c].Eval();
  return v;
}

void ExpressionField::velocities(std::span<const Vec3> x, double t, std::span<Vec3> out) const {
  std::lock_guard lock(mutex_);
  const std::size_t threads = static_cast<std::size_t>(std::max(1, omp_get_max_threads()));
  while (workspaces_.size() < threads) workspaces_.push_back(makeWorkspace());
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(x.size());
  // Each thread evaluates one contiguous chunk in bulk mode with its own parsers.
#pragma omp parallel num_threads(static_cast<int>(threads)) if(n >= kParallelMinItems)
  {
    const std::ptrdiff_t nt = omp_get_num_threads(), id = omp_get_thread_num();
    const std::ptrdiff_t begin = n * id / nt, end = n * (id + 1) / nt, m = end - begin;
    if (m > 0) {
      Workspace& ws = *workspaces_[static_cast<std::size_t>(id)];
      ws.define(static_cast<std::size_t>(m));
      for (std::ptrdiff_t i = 0; i < m; ++i) {
        const Vec3& p = x[begin + i];
        ws.x[i] = p.x();
        ws.y[i] = p.y();
        ws.z[i] = p.z();
        ws.t[i] = t;
      }
      for (int c = 0; c < 3; ++c) ws.parsers[c].Eval(ws.result[c].data(), static_cast<int>(m));
      for (std::ptrdiff_t i = 0; i < m; ++i)
        out[begin + i] = Vec3(ws.result[0][i], ws.result[1][i], ws.result[2][i]);
    }
  }
}

std::string ExpressionField::describe() const {
  return "expression field (" + params_.vx + ", " + params_.vy + ", " + params_.vz + ")";
}

std::string ExpressionField::describeComponent(int c) const {
  if (c < 0 || c > 2) return {};
  const std::array<const std::string*, 3> exprs = {&params_.vx, &params_.vy, &params_.vz};
  return std::string(kComponent[c]) + " = \"" + *exprs[c] + "\"";
}

VelocityFieldEntry expressionFieldEntry() {
  return {"expression", "Velocity components as muparser expressions of x, y, z, t and the named parameters.",
          {ParamSpec("vx", ParamType::String, "x component.").byDefault(std::string("0")),
           ParamSpec("vy", ParamType::String, "y component.").byDefault(std::string("0")),
           ParamSpec("vz", ParamType::String, "z component.").byDefault(std::string("0")),
           ParamSpec("parameters", ParamType::String,
                     "Named constants for the expressions, as \"name=value, name=value\".")
               .whenAbsent("no parameters")},
          [](const ParamValues& p) {
            ExpressionFieldParams params{.vx = p.getString("vx"), .vy = p.getString("vy"), .vz = p.getString("vz")};
            if (p.has("parameters")) params.parameters = parseExpressionParameters(p.getString("parameters"));
            return std::make_shared<const ExpressionField>(std::move(params));
          }};
}

}  // namespace tessella::growth
