// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Errors of Python code that runs inside a cell division (a custom property
// division function). Tissue::splitCell calls it after the topology has
// changed and before the lineage is updated, so an exception unwinding
// through it would leave the tissue half-divided. The wrapper stores the
// error instead (and gives both parts the mother's value); the binding that
// started the division raises it once the tissue is consistent again.
#include <exception>
#include <utility>

namespace tessella::python {

/// The pending error (one per module: inline).
inline std::exception_ptr& deferredError() {
  static std::exception_ptr error;
  return error;
}

/// Raises the error a division stored, if any.
inline void raiseDeferredError() {
  if (std::exception_ptr e = std::exchange(deferredError(), nullptr)) std::rethrow_exception(e);
}

}  // namespace tessella::python
