// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Errors raised by solvers/. All derive from SolverError, itself a tessella::Error
// (the root of every error Tessella throws on purpose), so a caller can catch
// every Tessella error, the solver family, or one kind when it can react to it.

#include "tessella/tissue/errors.hpp"

namespace tessella::solvers {

/// Base of every error thrown by solvers/.
class SolverError : public Error {
 public:
  using Error::Error;
};

/// The problem as posed is ill-defined: bad sizes, negative diffusivity or
/// modulus, a singular steady problem, an unconstrained elastic body, ...
class InvalidProblemError : public SolverError {
 public:
  using SolverError::SolverError;
};

/// A factorisation failed: the matrix is singular or not positive definite.
class FactorizationError : public SolverError {
 public:
  using SolverError::SolverError;
};

/// An iterative solve stopped before reaching its tolerance.
class ConvergenceError : public SolverError {
 public:
  using SolverError::SolverError;
};

}  // namespace tessella::solvers
