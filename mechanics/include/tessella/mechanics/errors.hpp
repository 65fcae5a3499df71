// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Errors raised by mechanics/. Both derive from tessella::Error.

#include "tessella/tissue/errors.hpp"

namespace tessella::mechanics {

/// Base of every error thrown by mechanics/.
class MechanicsError : public Error {
 public:
  using Error::Error;
};

/// The quasi-static equilibrium was not reached (Newton ran out of iterations,
/// or the line search found no decrease of the energy). The message names the
/// context given by the caller (step, time), the iterations and the residual;
/// the positions passed in were restored before the throw.
class EquilibriumError : public MechanicsError {
 public:
  EquilibriumError(const std::string& what, int iterations, double residual)
      : MechanicsError(what), iterations_(iterations), residual_(residual) {}
  int iterations() const { return iterations_; }
  double residual() const { return residual_; }

 private:
  int iterations_;
  double residual_;
};

}  // namespace tessella::mechanics
