#pragma once
// A growth step that leaves the tissue as it was when it fails. The
// integrator restores positions itself on a GeometryError, but an exception
// from a Python field in Heun's second stage would leave the predictor's
// positions behind: Python models catch exceptions and carry on, so the
// bindings restore positions and clock for every failure.
#include <exception>
#include <vector>

#include "tessella/growth/growth_integrator.hpp"

namespace tessella::python {

/// Runs step(), a growth step of t; positions and clock restored if it throws.
template <typename Step>
void restoringOnError(Tissue& t, Step&& step) {
  const std::vector<Vec3> before(t.positions().begin(), t.positions().end());
  const double time = t.time();
  try {
    step();
  } catch (...) {
    std::ranges::copy(before, t.mutablePositions().begin());
    t.setTime(time);
    throw;
  }
}

inline void stepRestoringOnError(growth::GrowthIntegrator& integrator, Tissue& t, double dt) {
  restoringOnError(t, [&] { integrator.step(t, dt); });
}

}  // namespace tessella::python
