// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A velocity field written as three expressions (muparser syntax) of x, y, z,
// t and named parameters, e.g. vx = "r*x", vy = "r*y", vz = "0".
// Expressions are parsed once, at construction: a syntax error or an unknown
// name raises InputError quoting the component, the expression, muparser's
// message and the character position. Batched evaluation uses muparser's bulk
// mode with one parser set per OpenMP thread (a parser is not thread-safe).

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "tessella/growth/velocity_field.hpp"

namespace tessella::growth {

struct ExpressionFieldParams {
  std::string vx = "0";
  std::string vy = "0";
  std::string vz = "0";
  /// Named constants usable in the expressions (not x, y, z or t).
  std::map<std::string, double> parameters{};
};

/// "r=0.1, k=2" -> {r: 0.1, k: 2}: named constants written as text (the
/// expression field's `parameters`). A ParamError at "parameters" quotes the
/// item that is not name=number or names one given twice.
std::map<std::string, double> parseExpressionParameters(const std::string& text);

class ExpressionField final : public VelocityField {
 public:
  explicit ExpressionField(ExpressionFieldParams params);
  ~ExpressionField() override;
  ExpressionField(const ExpressionField&) = delete;
  ExpressionField& operator=(const ExpressionField&) = delete;

  Vec3 velocity(const Vec3& x, double t) const override;
  void velocities(std::span<const Vec3> x, double t, std::span<Vec3> out) const override;
  std::string describe() const override;
  /// `vx = "..."` (c = 0), `vy = "..."`, `vz = "..."`.
  std::string describeComponent(int c) const override;
  const ExpressionFieldParams& params() const { return params_; }

 private:
  struct Workspace;  // three parsers and their variable buffers
  std::unique_ptr<Workspace> makeWorkspace() const;

  ExpressionFieldParams params_;
  // One workspace per OpenMP thread, grown before each parallel region; the
  // mutex makes concurrent calls from outside OpenMP safe (they serialise).
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<Workspace>> workspaces_;
};

}  // namespace tessella::growth
