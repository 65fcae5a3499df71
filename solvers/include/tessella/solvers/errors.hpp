#pragma once
// Errors raised by solvers/. All derive from SolverError (a std::runtime_error)
// so a caller can catch the family at once, or one kind when it can react to it.

#include <stdexcept>

namespace tessella {

/// Base of every error thrown by solvers/.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
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

}  // namespace tessella
