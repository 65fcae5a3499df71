// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private helper: deterministic OpenMP assembly. Element matrices are computed
// in parallel into fixed slots of a preallocated triplet array (slot = element
// index), then summed by setFromTriplets in that fixed order. The floating-point
// sums are therefore the same for any thread count: bit-identical results.

#include "tessella/solvers/linear_solver.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
#include <exception>
#include <limits>
#include <vector>

namespace tessella::solvers::detail {

/// Element matrix storage: up to 12 x 12 (a tetrahedron with 3 displacement components).
using LocalMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 12>;

/// compute(item, ke, dofs) must fill the local_size x local_size matrix ke and
/// the local_size global indices dofs[]; it runs concurrently for different items.
template <typename Compute>
SparseMatrix assembleElementwise(int num_items, int local_size, int global_size, Compute&& compute) {
  const std::size_t block = static_cast<std::size_t>(local_size) * static_cast<std::size_t>(local_size);
  std::vector<Eigen::Triplet<double>> triplets(static_cast<std::size_t>(num_items) * block);
  // An exception must not leave an OpenMP region: keep the one from the lowest
  // item index (deterministic message), rethrow after the loop.
  std::exception_ptr error;
  int error_item = std::numeric_limits<int>::max();
#pragma omp parallel for schedule(static)
  for (int item = 0; item < num_items; ++item) {
    try {
      LocalMatrix ke(local_size, local_size);
      int dofs[12];
      compute(item, ke, dofs);
      std::size_t slot = static_cast<std::size_t>(item) * block;
      for (int a = 0; a < local_size; ++a)
        for (int b = 0; b < local_size; ++b) triplets[slot++] = Eigen::Triplet<double>(dofs[a], dofs[b], ke(a, b));
    } catch (...) {
#pragma omp critical(tessella_assembly_error)
      if (item < error_item) {
        error_item = item;
        error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
  SparseMatrix A(global_size, global_size);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

/// Runs f(item) for all items in parallel, rethrowing the lowest-index exception.
template <typename F>
void parallelFor(int num_items, F&& f) {
  std::exception_ptr error;
  int error_item = std::numeric_limits<int>::max();
#pragma omp parallel for schedule(static)
  for (int item = 0; item < num_items; ++item) {
    try {
      f(item);
    } catch (...) {
#pragma omp critical(tessella_parallel_for_error)
      if (item < error_item) {
        error_item = item;
        error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace tessella::solvers::detail
