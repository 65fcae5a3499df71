// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/network_integrator.hpp"

#include <cvode/cvode.h>
#include <omp.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include "tessella/tissue/format.hpp"
#include "vector_kernels.hpp"

namespace tessella::networks {

IntegratorStatistics& IntegratorStatistics::operator+=(const IntegratorStatistics& o) {
  steps += o.steps;
  rhs_evaluations += o.rhs_evaluations;
  jacobian_evaluations += o.jacobian_evaluations;
  nonlinear_iterations += o.nonlinear_iterations;
  error_test_failures += o.error_test_failures;
  linear_setups += o.linear_setups;
  linear_solves += o.linear_solves;
  linear_iterations += o.linear_iterations;
  rhs_seconds += o.rhs_seconds;
  jacobian_seconds += o.jacobian_seconds;
  setup_seconds += o.setup_seconds;
  solve_seconds += o.solve_seconds;
  return *this;
}

const EnumTable<LinearSolver>& linearSolvers() {
  static const EnumTable<LinearSolver> table(
      "linear solver",
      {{"klu", LinearSolver::Klu, "Sparse LU (KLU) of the Newton matrix: exact solves."},
       {"gmres", LinearSolver::Gmres,
        "GMRES with a block-Jacobi preconditioner per cell: much cheaper per solve on large tissues."}});
  return table;
}

namespace {
using Clock = std::chrono::steady_clock;
// From this many rows on, J v and the preconditioner are split over OpenMP threads (row by row, so the
// results do not depend on the number of threads).
constexpr std::size_t kParallelRows = 131072;
// From this many cells on, the preconditioner's blocks are inverted over OpenMP threads.
constexpr std::size_t kParallelCells = 4096;

// The inverse of the S x S matrix `a` (column-major, overwritten) into `inverse` (column-major), by
// Gauss-Jordan elimination with partial pivoting; false when a pivot is zero or not finite.
bool invertBlock(std::size_t S, double* a, double* inverse) {
  auto A = [&](std::size_t r, std::size_t c) -> double& { return a[c * S + r]; };
  auto X = [&](std::size_t r, std::size_t c) -> double& { return inverse[c * S + r]; };
  for (std::size_t r = 0; r < S; ++r)
    for (std::size_t c = 0; c < S; ++c) X(r, c) = r == c ? 1.0 : 0.0;
  for (std::size_t k = 0; k < S; ++k) {
    std::size_t pivot = k;
    for (std::size_t r = k + 1; r < S; ++r)
      if (std::abs(A(r, k)) > std::abs(A(pivot, k))) pivot = r;
    const double d = A(pivot, k);
    if (!(std::abs(d) > 0) || !std::isfinite(d)) return false;
    if (pivot != k)
      for (std::size_t c = 0; c < S; ++c) {
        std::swap(A(k, c), A(pivot, c));
        std::swap(X(k, c), X(pivot, c));
      }
    for (std::size_t c = 0; c < S; ++c) {
      A(k, c) /= d;
      X(k, c) /= d;
    }
    for (std::size_t r = 0; r < S; ++r) {
      if (r == k) continue;
      const double f = A(r, k);
      if (f == 0.0) continue;
      for (std::size_t c = 0; c < S; ++c) {
        A(r, c) -= f * A(k, c);
        X(r, c) -= f * X(k, c);
      }
    }
  }
  for (std::size_t i = 0; i < S * S; ++i)
    if (!std::isfinite(inverse[i])) return false;
  return true;
}
double since(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }
}  // namespace

struct NetworkIntegrator::Impl {
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver solver = nullptr;
  void* cvode = nullptr;
  NetworkSystem* system = nullptr;
  CsrMatrix J;
  std::vector<std::uint32_t> column32;  // GMRES: J's column indices, narrower for J v (the pattern is fixed)
  std::exception_ptr failure;  // an exception thrown inside a callback
  std::string last_message;    // CVODE's last error message
  std::size_t species = 0;     // S: the size of a preconditioner block
  std::size_t cells = 0;       // n: the amounts are the first n S entries of the state (then PIN densities)
  std::vector<std::size_t> conserved;  // GMRES: the species without reactions (their totals are kept)
  std::vector<double> block_inverse;  // GMRES: per cell, the S x S inverse of I - gamma J's block (column-major)
  bool timers = false;
  double relative_tolerance = 0, absolute_tolerance = 0;  // errorWeights
  int threads = 1;  // OpenMP threads of the callbacks (NetworkSystem::threads())
  IntegratorStatistics* stats = nullptr;  // where the timers add
  // The linear solver's own setup and solve, wrapped by timedSetup / timedSolve (timers, conservation).
  int (*inner_setup)(SUNLinearSolver, SUNMatrix) = nullptr;
  int (*inner_solve)(SUNLinearSolver, SUNMatrix, N_Vector, N_Vector, realtype) = nullptr;
  // The integrator whose linear solver runs (the wrappers receive only the solver).
  static thread_local Impl* active;

  ~Impl() {
    if (cvode) CVodeFree(&cvode);
    if (solver) SUNLinSolFree(solver);
    if (A) SUNMatDestroy(A);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
  }

  static int timedSetup(SUNLinearSolver S, SUNMatrix A) {
    Impl* self = active;
    const auto a = Clock::now();
    const double jacobian_before = self->stats->jacobian_seconds;  // GMRES' setup evaluates the Jacobian
    const int flag = self->inner_setup(S, A);
    self->stats->setup_seconds += since(a) - (self->stats->jacobian_seconds - jacobian_before);
    return flag;
  }

  // GMRES: J v with the Jacobian of the last preconditioner setup.
  static int jtimes(N_Vector v, N_Vector Jv, realtype, N_Vector, N_Vector, void* data, N_Vector) {
    const auto* self = static_cast<Impl*>(data);
    const CsrMatrix& J = self->J;
    const double* x = N_VGetArrayPointer_Serial(v);
    double* out = N_VGetArrayPointer_Serial(Jv);
    const auto rows = static_cast<std::ptrdiff_t>(J.rows);
    const std::uint32_t* column = self->column32.data();
#pragma omp parallel for schedule(static) if (self->threads > 1 && J.rows >= kParallelRows) num_threads(self->threads)
    for (std::ptrdiff_t r = 0; r < rows; ++r) {
      double sum = 0.0;
      for (std::size_t k = J.row_start[static_cast<std::size_t>(r)]; k < J.row_start[static_cast<std::size_t>(r) + 1];
           ++k)
        sum += J.value[k] * x[column[k]];
      out[r] = sum;
    }
    return 0;
  }

  // GMRES' preconditioner setup: a new Jacobian unless CVODE says the last is good (jok), then per cell
  // the inverse of the species block of I - gamma J.
  static int psetup(realtype t, N_Vector y, N_Vector fy, booleantype jok, booleantype* jcur, realtype gamma,
                    void* data) {
    auto* self = static_cast<Impl*>(data);
    if (!jok) {
      if (jac(t, y, fy, nullptr, data, nullptr, nullptr, nullptr) != 0) return -1;
      ++self->stats->jacobian_evaluations;  // CVodeGetNumJacEvals counts matrix-based solvers' only
      *jcur = SUNTRUE;
    } else {
      *jcur = SUNFALSE;
    }
    const std::size_t S = self->species, n = self->cells;
    bool singular = false;
    const int team = static_cast<int>(self->system->threads());
#pragma omp parallel if (team > 1 && n >= kParallelCells) num_threads(team) reduction(|| : singular)
    {
      std::vector<double> block(S * S);
#pragma omp for schedule(static)
      for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(n); ++k) {
        const auto c = static_cast<std::size_t>(k);
        const CsrMatrix& J = self->J;
        for (std::size_t a = 0; a < S; ++a) {
          for (std::size_t b = 0; b < S; ++b) block[b * S + a] = a == b ? 1.0 : 0.0;
          // The row's entries in the cell's own columns [c S, (c + 1) S) (columns ascending).
          const std::size_t r = c * S + a, end = J.row_start[r + 1];
          std::size_t e = static_cast<std::size_t>(
              std::lower_bound(J.column.begin() + static_cast<std::ptrdiff_t>(J.row_start[r]),
                               J.column.begin() + static_cast<std::ptrdiff_t>(end), c * S) -
              J.column.begin());
          for (; e < end && J.column[e] < (c + 1) * S; ++e)
            block[(J.column[e] - c * S) * S + a] = (a == J.column[e] - c * S ? 1.0 : 0.0) - gamma * J.value[e];
        }
        singular = !invertBlock(S, block.data(), &self->block_inverse[c * S * S]) || singular;
      }
    }
    if (singular) return 1;  // recoverable: CVODE retries with a smaller step
    // PIN densities (after the amounts): the inverse of their diagonal entry.
    for (std::size_t r = n * S; r < self->J.rows; ++r) {
      const double d = 1.0 - gamma * self->J.at(r, r);
      if (!(std::abs(d) > 0)) return 1;
      self->block_inverse[n * S * S + (r - n * S)] = 1.0 / d;
    }
    return 0;
  }

  // z = the block inverses times r, cell by cell; `Fixed` > 0: S == Fixed known at compile time (the loops
  // unrolled; the same operations in the same order).
  template <std::size_t Fixed>
  void applyBlocks(const double* in, double* out) const {
    const std::size_t S = Fixed > 0 ? Fixed : species, n = cells;
#pragma omp parallel for schedule(static) if (threads > 1 && n * S >= kParallelRows) num_threads(threads)
    for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(n); ++k) {
      const auto c = static_cast<std::size_t>(k);
      const double* M = &block_inverse[c * S * S];
      const double* x = &in[c * S];
      for (std::size_t a = 0; a < S; ++a) {
        double sum = 0.0;
        for (std::size_t b = 0; b < S; ++b) sum += M[b * S + a] * x[b];
        out[c * S + a] = sum;
      }
    }
  }

  static int psolve(realtype, N_Vector, N_Vector, N_Vector r, N_Vector z, realtype, realtype, int, void* data) {
    auto* self = static_cast<Impl*>(data);
    const std::size_t S = self->species, n = self->cells;
    const double* in = N_VGetArrayPointer_Serial(r);
    double* out = N_VGetArrayPointer_Serial(z);
    switch (S) {
      case 1: self->applyBlocks<1>(in, out); break;
      case 2: self->applyBlocks<2>(in, out); break;
      case 3: self->applyBlocks<3>(in, out); break;
      case 4: self->applyBlocks<4>(in, out); break;
      default: self->applyBlocks<0>(in, out);
    }
    for (std::size_t k = n * S; k < self->J.rows; ++k) out[k] = self->block_inverse[n * S * S + (k - n * S)] * in[k];
    return 0;
  }
  static int timedSolve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype tol) {
    Impl* self = active;
    const auto a = self->timers ? Clock::now() : Clock::time_point{};
    const int flag = self->inner_solve(S, A, x, b, tol);
    if (flag == 0 && !self->conserved.empty()) self->conserve(x, b);
    if (self->timers) {
      self->stats->solve_seconds += since(a);
      ++self->stats->linear_solves;
    }
    return flag;
  }

  // GMRES: for a species without reactions, the columns of I - gamma J sum to one over its rows (transport
  // moves amounts), so an exact solve x of (I - gamma J) x = b has sum x = sum b over the cells: the Newton
  // iteration keeps the total amount. GMRES' approximate x does not; adding the missing amount evenly to
  // every cell restores the sum (a change within the linear solver's tolerance).
  void conserve(N_Vector xv, N_Vector bv) const {
    const double* bb = N_VGetArrayPointer_Serial(bv);
    double* xx = N_VGetArrayPointer_Serial(xv);
    const std::size_t S = species, n = cells;
    for (std::size_t s : conserved) {
      double missing = 0.0;
      for (std::size_t c = 0; c < n; ++c) missing += bb[c * S + s] - xx[c * S + s];
      const double each = missing / static_cast<double>(n);
      for (std::size_t c = 0; c < n; ++c) xx[c * S + s] += each;
    }
  }

  static int rhs(realtype t, N_Vector y, N_Vector ydot, void* data) {
    auto* self = static_cast<Impl*>(data);
    const auto start = self->timers ? Clock::now() : Clock::time_point{};
    struct Timer {
      Impl* self;
      Clock::time_point start;
      double IntegratorStatistics::*field;
      ~Timer() {
        if (self->timers) self->stats->*field += since(start);
      }
    } timer{self, start, &IntegratorStatistics::rhs_seconds};
    try {
      const auto n = static_cast<std::size_t>(N_VGetLength_Serial(y));
      self->system->rhs(t, std::span<const double>(N_VGetArrayPointer_Serial(y), n),
                        std::span<double>(N_VGetArrayPointer_Serial(ydot), n));
      return 0;
    } catch (...) {
      self->failure = std::current_exception();
      return -1;  // unrecoverable
    }
  }

  static int jac(realtype t, N_Vector y, N_Vector /*fy*/, SUNMatrix A, void* data, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(data);
    const auto start = self->timers ? Clock::now() : Clock::time_point{};
    struct Timer {
      Impl* self;
      Clock::time_point start;
      ~Timer() {
        if (self->timers) self->stats->jacobian_seconds += since(start);
      }
    } timer{self, start};
    try {
      const auto n = static_cast<std::size_t>(N_VGetLength_Serial(y));
      self->system->jacobian(t, std::span<const double>(N_VGetArrayPointer_Serial(y), n), self->J);
      if (!A) return 0;  // GMRES keeps the CsrMatrix only
      const CsrMatrix& J = self->J;
      sunindextype* rowptr = SUNSparseMatrix_IndexPointers(A);
      sunindextype* colidx = SUNSparseMatrix_IndexValues(A);
      realtype* values = SUNSparseMatrix_Data(A);
      for (std::size_t r = 0; r <= J.rows; ++r) rowptr[r] = static_cast<sunindextype>(J.row_start[r]);
      for (std::size_t k = 0; k < J.column.size(); ++k) {
        colidx[k] = static_cast<sunindextype>(J.column[k]);
        values[k] = J.value[k];
      }
      return 0;
    } catch (...) {
      self->failure = std::current_exception();
      return -1;
    }
  }

  // The error weights 1 / (rtol |y_i| + atol) in one pass: what CVODE's scalar tolerances compute in five
  // (|y|, times rtol, plus atol, the minimum, the inverse), the same operations on every entry.
  static int errorWeights(N_Vector y, N_Vector ewt, void* data) {
    const auto* self = static_cast<Impl*>(data);
    const double rtol = self->relative_tolerance, atol = self->absolute_tolerance;
    const double* yy = N_VGetArrayPointer_Serial(y);
    double* w = N_VGetArrayPointer_Serial(ewt);
    const auto n = static_cast<std::size_t>(N_VGetLength_Serial(y));
    bool positive = true;
    for (std::size_t i = 0; i < n; ++i) {
      const double d = rtol * std::abs(yy[i]) + atol;
      positive = positive && d > 0;
      w[i] = 1.0 / d;
    }
    return positive ? 0 : -1;
  }

  static void errorHandler(int, const char*, const char*, char* message, void* data) {
    static_cast<Impl*>(data)->last_message = message ? message : "";
  }
};

thread_local NetworkIntegrator::Impl* NetworkIntegrator::Impl::active = nullptr;

namespace {
std::string flagName(int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string out = name ? name : std::to_string(flag);
  std::free(name);
  return out;
}

void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string("network integrator: ") + what + " failed (flag " +
                                         std::to_string(flag) + ")");
}
}  // namespace

NetworkIntegrator::NetworkIntegrator(NetworkSystem& system, IntegratorOptions options)
    : impl_(std::make_unique<Impl>()), system_(system), options_(options) {
  auto positive = [](double v, const char* what) {
    if (!(std::isfinite(v) && v > 0.0))
      throw InputError(std::string("network integrator: ") + what + " " + formatNumber(v) + " must be > 0");
  };
  positive(options_.relative_tolerance, "relative_tolerance");
  positive(options_.absolute_tolerance, "absolute_tolerance");
  if (options_.max_steps < 1) throw InputError("network integrator: max_steps must be >= 1");
  if (options_.setup_frequency < 0)
    throw InputError("network integrator: setup_frequency " + std::to_string(options_.setup_frequency) +
                     " must be >= 0");
  if (options_.jacobian_frequency < 0)
    throw InputError("network integrator: jacobian_frequency " + std::to_string(options_.jacobian_frequency) +
                     " must be >= 0");
  if (!(std::isfinite(options_.max_step) && options_.max_step >= 0.0))
    throw InputError("network integrator: max_step " + formatNumber(options_.max_step) + " must be >= 0");
  if (options_.threads < 0)
    throw InputError("network integrator: threads " + std::to_string(options_.threads) + " must be >= 0");
  if (system_.size() == 0) throw InputError("network integrator: the system has no cells");
  Impl& m = *impl_;
  system_.setThreads(static_cast<std::size_t>(options_.threads));
  m.threads = static_cast<int>(system_.threads());
  m.system = &system_;
  m.timers = options_.timers;
  m.stats = &stats_;
  check(SUNContext_Create(nullptr, &m.context), "SUNContext_Create");
  const auto n = static_cast<sunindextype>(system_.size());
  m.y = N_VNew_Serial(n, m.context);
  if (!m.y) throw std::runtime_error("network integrator: N_VNew_Serial failed");
  useFastVectorKernels(m.y);  // before CVODE and SPGMR clone it
  m.J = system_.pattern();
  m.species = system_.numSpecies();
  m.cells = system_.numCells();
  const bool gmres = options_.linear_solver == LinearSolver::Gmres;
  if (gmres) {
    if (m.J.rows > std::numeric_limits<std::uint32_t>::max())
      throw InputError("network integrator: " + std::to_string(m.J.rows) + " unknowns are too many for gmres");
    m.column32.assign(m.J.column.begin(), m.J.column.end());
    m.block_inverse.assign(system_.numCells() * m.species * m.species + system_.numPinStates(), 0.0);
    m.solver = SUNLinSol_SPGMR(m.y, SUN_PREC_LEFT, 0, m.context);
    if (!m.solver) throw std::runtime_error("network integrator: SUNLinSol_SPGMR failed");
  } else {
    m.A = SUNSparseMatrix(n, n, static_cast<sunindextype>(std::max<std::size_t>(m.J.column.size(), 1)), CSR_MAT,
                          m.context);
    if (!m.A) throw std::runtime_error("network integrator: SUNSparseMatrix failed");
    m.solver = SUNLinSol_KLU(m.y, m.A, m.context);
    if (!m.solver) throw std::runtime_error("network integrator: SUNLinSol_KLU failed");
    // AMD: the Jacobian's pattern is symmetric (cell adjacency), where AMD fills in less than COLAMD.
    check(SUNLinSol_KLUSetOrdering(m.solver, 0), "SUNLinSol_KLUSetOrdering");
  }
  if (gmres)
    for (std::size_t s = 0; s < m.species; ++s)
      if (system_.model().species[s].reaction.empty()) m.conserved.push_back(s);
  if (m.timers || !m.conserved.empty()) {
    m.inner_setup = m.solver->ops->setup;
    m.inner_solve = m.solver->ops->solve;
    if (m.timers) m.solver->ops->setup = &Impl::timedSetup;
    m.solver->ops->solve = &Impl::timedSolve;
  }
  m.cvode = CVodeCreate(CV_BDF, m.context);
  if (!m.cvode) throw std::runtime_error("network integrator: CVodeCreate failed");
  check(CVodeSetErrHandlerFn(m.cvode, &Impl::errorHandler, &m), "CVodeSetErrHandlerFn");
  check(CVodeInit(m.cvode, &Impl::rhs, 0.0, m.y), "CVodeInit");
  check(CVodeSetUserData(m.cvode, &m), "CVodeSetUserData");
  m.relative_tolerance = options_.relative_tolerance;
  m.absolute_tolerance = options_.absolute_tolerance;
  check(CVodeWFtolerances(m.cvode, &Impl::errorWeights), "CVodeWFtolerances");
  check(CVodeSetLinearSolver(m.cvode, m.solver, m.A), "CVodeSetLinearSolver");
  if (gmres) {
    check(CVodeSetPreconditioner(m.cvode, &Impl::psetup, &Impl::psolve), "CVodeSetPreconditioner");
    check(CVodeSetJacTimes(m.cvode, nullptr, &Impl::jtimes), "CVodeSetJacTimes");
  } else {
    check(CVodeSetJacFn(m.cvode, &Impl::jac), "CVodeSetJacFn");
  }
  check(CVodeSetMaxNumSteps(m.cvode, options_.max_steps), "CVodeSetMaxNumSteps");
  if (options_.max_step > 0) check(CVodeSetMaxStep(m.cvode, options_.max_step), "CVodeSetMaxStep");
  if (options_.setup_frequency > 0)
    check(CVodeSetLSetupFrequency(m.cvode, options_.setup_frequency), "CVodeSetLSetupFrequency");
  if (options_.jacobian_frequency > 0)
    check(CVodeSetJacEvalFrequency(m.cvode, options_.jacobian_frequency), "CVodeSetJacEvalFrequency");
}

NetworkIntegrator::~NetworkIntegrator() = default;

void NetworkIntegrator::advance(std::span<double> y, double t0, double t1) {
  if (y.size() != system_.size())
    throw InputError("network integrator: " + std::to_string(y.size()) + " amounts for a system of " +
                     std::to_string(system_.size()));
  if (!(t1 > t0)) throw InputError("network integrator: advance needs t1 > t0");
  Impl& m = *impl_;
  double* state = N_VGetArrayPointer_Serial(m.y);
  std::copy(y.begin(), y.end(), state);
  m.failure = nullptr;
  check(CVodeReInit(m.cvode, t0, m.y), "CVodeReInit");
  check(CVodeSetStopTime(m.cvode, t1), "CVodeSetStopTime");
  realtype t = t0;
  Impl* const outer = Impl::active;
  Impl::active = &m;
  struct KernelThreads {  // the vector kernels' threads for this call, restored however it ends
    int previous;
    ~KernelThreads() { setVectorKernelThreads(previous); }
  } kernel_threads{setVectorKernelThreads(m.threads)};
  struct DynamicThreads {  // omp_set_dynamic for this call (adapt_threads), restored however it ends
    int previous;
    ~DynamicThreads() { omp_set_dynamic(previous); }
  } dynamic_threads{omp_get_dynamic()};
  if (m.threads > 1 && options_.adapt_threads) omp_set_dynamic(1);
  const int flag = CVode(m.cvode, t1, m.y, &t, CV_NORMAL);
  Impl::active = outer;
  long v = 0;
  auto add = [&](int (*get)(void*, long*), long& total) {
    if (get(m.cvode, &v) >= 0) total += v;
  };
  add(CVodeGetNumSteps, stats_.steps);
  add(CVodeGetNumRhsEvals, stats_.rhs_evaluations);
  add(CVodeGetNumJacEvals, stats_.jacobian_evaluations);
  add(CVodeGetNumNonlinSolvIters, stats_.nonlinear_iterations);
  add(CVodeGetNumErrTestFails, stats_.error_test_failures);
  add(CVodeGetNumLinSolvSetups, stats_.linear_setups);
  add(CVodeGetNumLinIters, stats_.linear_iterations);
  if (m.failure) std::rethrow_exception(m.failure);
  if (flag < 0) {
    // The worst component: largest |local error| * weight.
    N_Vector ele = N_VClone(m.y), w = N_VClone(m.y);
    std::size_t worst = 0;
    double worst_value = -1.0;
    if (CVodeGetEstLocalErrors(m.cvode, ele) >= 0 && CVodeGetErrWeights(m.cvode, w) >= 0) {
      const double* e = N_VGetArrayPointer_Serial(ele);
      const double* wt = N_VGetArrayPointer_Serial(w);
      for (std::size_t k = 0; k < system_.size(); ++k) {
        const double value = std::abs(e[k] * wt[k]);
        if (value > worst_value) {
          worst_value = value;
          worst = k;
        }
      }
    }
    N_VDestroy(ele);
    N_VDestroy(w);
    const std::size_t S = system_.numSpecies(), amounts = S * system_.numCells();
    std::size_t cell = S ? worst / S : 0;
    std::string species = system_.model().species[S ? worst % S : 0].name;
    std::string where = "species '" + species + "' of cell " + std::to_string(cell);
    if (worst >= amounts) {  // a PIN density
      const std::size_t k = (worst - amounts) / 2;
      const bool side_i = (worst - amounts) % 2 == 0;
      const NetworkInterface& f = system_.graph().interfaces[k];
      cell = static_cast<std::size_t>(side_i ? f.cell_i : f.cell_j);
      species = system_.model().pin.species;
      where = "the PIN of '" + species + "' on cell " + std::to_string(cell) + "'s side of its interface with cell " +
              std::to_string(side_i ? f.cell_j : f.cell_i);
    }
    double reached = t;
    CVodeGetCurrentTime(m.cvode, &reached);
    std::ostringstream msg;
    msg << "network integration failed at t = " << formatNumber(reached) << " (integrating from "
        << formatNumber(t0) << " to " << formatNumber(t1) << "): CVODE " << flagName(flag);
    if (!m.last_message.empty()) msg << " (" << m.last_message << ")";
    msg << "; largest weighted local error in " << where << " ("
        << formatNumber(worst_value) << ")";
    throw NetworkIntegrationError(msg.str(), reached, flag, species, cell);
  }
  std::copy(state, state + y.size(), y.begin());
}

}  // namespace tessella::networks
