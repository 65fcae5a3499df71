// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Faster kernels for CVODE's and SPGMR's serial vectors: the reductions (dot
// products, weighted root-mean-square norms) summed in fixed blocks with
// independent partial sums instead of one long chain of additions, and the
// element-wise operations CVODE uses most, split over OpenMP threads for long
// vectors. The blocks do not depend on the number of threads, so the results
// are bit-identical for any thread count (they differ from SUNDIALS' own
// kernels in the last bits: another order of summation).

#include <nvector/nvector_serial.h>

namespace tessella::networks {

/// The number of OpenMP threads the kernels may use on long vectors in this
/// thread (1: none; set by NetworkIntegrator::advance for its duration).
/// Returns the previous value.
int setVectorKernelThreads(int threads);

/// Replaces the operations of the serial vector `v` (and so of every clone
/// made from it afterwards) with the kernels above, and enables the fused
/// operations (linear combinations, scale-add of several vectors, several dot
/// products) with kernels of the same kind.
void useFastVectorKernels(N_Vector v);

}  // namespace tessella::networks
