// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// PythonField: a velocity field written in Python.
//
// The Python function receives all points of one evaluation at once, as an
// (n, 3) float64 array, and the time, and returns an (n, 3) array of
// velocities (vectorised NumPy code, one call per integrator stage). It is
// called only from the thread that called into Tessella, which holds the
// GIL: GrowthIntegrator evaluates fields on its calling thread, outside its
// OpenMP loops, and this class overrides velocities() so the default
// per-point OpenMP loop never runs Python on a worker thread.
#include <string>

#include "bindings.hpp"
#include "tessella/growth/velocity_field.hpp"

namespace tessella::python {

class PythonField final : public growth::VelocityField {
 public:
  PythonField(py::function fn, std::string description);
  ~PythonField() override;
  Vec3 velocity(const Vec3& x, double t) const override;
  void velocities(std::span<const Vec3> x, double t, std::span<Vec3> out) const override;
  std::string describe() const override { return description_; }

 private:
  py::function fn_;
  std::string description_;
};

}  // namespace tessella::python
