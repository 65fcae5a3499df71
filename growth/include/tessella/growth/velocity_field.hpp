// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// VelocityField: a prescribed kinematic growth field v(x, t). The growth
// integrator moves every vertex (or every control vertex, see
// HarmonicInterpolator) with it.

#include <span>
#include <string>

#include "tessella/tissue/vec3.hpp"

namespace tessella::growth {

class VelocityField {
 public:
  virtual ~VelocityField() = default;

  /// Velocity at position x and time t.
  virtual Vec3 velocity(const Vec3& x, double t) const = 0;

  /// Velocities of many points at one time (out.size() == x.size()). The
  /// default runs velocity() in an OpenMP loop; fields with a per-call set-up
  /// cost (expressions) override it. Must be safe to call concurrently.
  virtual void velocities(std::span<const Vec3> x, double t, std::span<Vec3> out) const;

  /// Short description for logs and error messages.
  virtual std::string describe() const = 0;

  /// What computes component c (0, 1, 2 = x, y, z) when the field spells it
  /// out separately (an expression: `vx = "r*x"`); empty otherwise. Error
  /// messages about a non-finite component quote it.
  virtual std::string describeComponent(int /*c*/) const { return {}; }
};

}  // namespace tessella::growth
