// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "vector_kernels.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tessella::networks {

namespace {

using Index = sunindextype;
// Elements per reduction block (the blocks, not the threads, fix the order of summation) and the length
// from which an operation is split over threads: an operation takes tens of microseconds at 3e4 entries,
// where starting threads (or waiting for one on a loaded machine) costs as much.
constexpr Index kBlock = 4096;
constexpr Index kParallelMin = 131072;

thread_local int kernel_threads = 1;
bool parallel(Index n) { return kernel_threads > 1 && n >= kParallelMin; }

Index length(N_Vector v) { return NV_LENGTH_S(v); }
double* data(N_Vector v) { return NV_DATA_S(v); }

// sum over [0, n) of term(i), as the in-order sum of the blocks' sums, each with four partial sums.
template <class Term>
double blockSum(Index n, Term term) {
  const Index blocks = (n + kBlock - 1) / kBlock;
  double small[64];
  std::vector<double> large;
  double* partial = small;
  if (blocks > 64) {
    large.resize(static_cast<std::size_t>(blocks));
    partial = large.data();
  }
#pragma omp parallel for schedule(static) if (parallel(n)) num_threads(kernel_threads)
  for (Index b = 0; b < blocks; ++b) {
    const Index first = b * kBlock, last = std::min(n, first + kBlock);
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    Index i = first;
    for (; i + 4 <= last; i += 4) {
      s0 += term(i);
      s1 += term(i + 1);
      s2 += term(i + 2);
      s3 += term(i + 3);
    }
    for (; i < last; ++i) s0 += term(i);
    partial[b] = (s0 + s1) + (s2 + s3);
  }
  double sum = 0.0;
  for (Index b = 0; b < blocks; ++b) sum += partial[b];
  return sum;
}

// out[i] = op(i) for i in [0, n).
template <class Op>
void forEach(Index n, Op op) {
#pragma omp parallel for schedule(static) if (parallel(n)) num_threads(kernel_threads)
  for (Index i = 0; i < n; ++i) op(i);
}

void linearSum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  if (a == 1.0 && b == 1.0)
    forEach(length(z), [&](Index i) { zd[i] = xd[i] + yd[i]; });
  else if (a == 1.0 && b == -1.0)
    forEach(length(z), [&](Index i) { zd[i] = xd[i] - yd[i]; });
  else if (a == -1.0 && b == 1.0)
    forEach(length(z), [&](Index i) { zd[i] = yd[i] - xd[i]; });
  else
    forEach(length(z), [&](Index i) { zd[i] = a * xd[i] + b * yd[i]; });
}

void constant(realtype c, N_Vector z) {
  double* zd = data(z);
  forEach(length(z), [&](Index i) { zd[i] = c; });
}

void product(N_Vector x, N_Vector y, N_Vector z) {
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  forEach(length(z), [&](Index i) { zd[i] = xd[i] * yd[i]; });
}

void quotient(N_Vector x, N_Vector y, N_Vector z) {
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  forEach(length(z), [&](Index i) { zd[i] = xd[i] / yd[i]; });
}

void scale(realtype c, N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  if (c == 1.0)
    forEach(length(z), [&](Index i) { zd[i] = xd[i]; });
  else if (c == -1.0)
    forEach(length(z), [&](Index i) { zd[i] = -xd[i]; });
  else
    forEach(length(z), [&](Index i) { zd[i] = c * xd[i]; });
}

void absolute(N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  forEach(length(z), [&](Index i) { zd[i] = std::abs(xd[i]); });
}

void inverse(N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  forEach(length(z), [&](Index i) { zd[i] = 1.0 / xd[i]; });
}

void addConstant(N_Vector x, realtype b, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  forEach(length(z), [&](Index i) { zd[i] = xd[i] + b; });
}

realtype dotProduct(N_Vector x, N_Vector y) {
  const double *xd = data(x), *yd = data(y);
  return blockSum(length(x), [&](Index i) { return xd[i] * yd[i]; });
}

realtype weightedSquareSum(N_Vector x, N_Vector w) {
  const double *xd = data(x), *wd = data(w);
  return blockSum(length(x), [&](Index i) {
    const double p = xd[i] * wd[i];
    return p * p;
  });
}

realtype wrmsNorm(N_Vector x, N_Vector w) {
  return std::sqrt(weightedSquareSum(x, w) / static_cast<double>(length(x)));
}

int linearCombination(int count, realtype* c, N_Vector* X, N_Vector z) {
  const Index n = length(z);
  double* zd = data(z);
  std::vector<const double*> xs(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) xs[static_cast<std::size_t>(k)] = data(X[k]);
  forEach(n, [&](Index i) {
    double sum = c[0] * xs[0][i];
    for (int k = 1; k < count; ++k) sum += c[k] * xs[static_cast<std::size_t>(k)][i];
    zd[i] = sum;
  });
  return 0;
}

int scaleAddMulti(int count, realtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  const Index n = length(x);
  const double* xd = data(x);
  for (int k = 0; k < count; ++k) {
    const double* yd = data(Y[k]);
    double* zd = data(Z[k]);
    const double ak = a[k];
    forEach(n, [&](Index i) { zd[i] = ak * xd[i] + yd[i]; });
  }
  return 0;
}

int dotProductMulti(int count, N_Vector x, N_Vector* Y, realtype* out) {
  for (int k = 0; k < count; ++k) out[k] = dotProduct(x, Y[k]);
  return 0;
}

}  // namespace

int setVectorKernelThreads(int threads) {
  const int previous = kernel_threads;
  kernel_threads = std::max(threads, 1);
  return previous;
}

void useFastVectorKernels(N_Vector v) {
  N_VEnableFusedOps_Serial(v, SUNTRUE);
  N_Vector_Ops ops = v->ops;
  ops->nvlinearsum = &linearSum;
  ops->nvconst = &constant;
  ops->nvprod = &product;
  ops->nvdiv = &quotient;
  ops->nvscale = &scale;
  ops->nvabs = &absolute;
  ops->nvinv = &inverse;
  ops->nvaddconst = &addConstant;
  ops->nvdotprod = &dotProduct;
  ops->nvdotprodlocal = &dotProduct;
  ops->nvwrmsnorm = &wrmsNorm;
  ops->nvwsqrsumlocal = &weightedSquareSum;
  ops->nvlinearcombination = &linearCombination;
  ops->nvscaleaddmulti = &scaleAddMulti;
  ops->nvdotprodmulti = &dotProductMulti;
}

}  // namespace tessella::networks
