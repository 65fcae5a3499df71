// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/network_integrator.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <sstream>

#include "tessella/tissue/format.hpp"

namespace tessella::networks {

struct NetworkIntegrator::Impl {
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver solver = nullptr;
  void* cvode = nullptr;
  NetworkSystem* system = nullptr;
  CsrMatrix J;
  std::exception_ptr failure;  // an exception thrown inside a callback
  std::string last_message;    // CVODE's last error message

  ~Impl() {
    if (cvode) CVodeFree(&cvode);
    if (solver) SUNLinSolFree(solver);
    if (A) SUNMatDestroy(A);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
  }

  static int rhs(realtype t, N_Vector y, N_Vector ydot, void* data) {
    auto* self = static_cast<Impl*>(data);
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
    try {
      const auto n = static_cast<std::size_t>(N_VGetLength_Serial(y));
      self->system->jacobian(t, std::span<const double>(N_VGetArrayPointer_Serial(y), n), self->J);
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

  static void errorHandler(int, const char*, const char*, char* message, void* data) {
    static_cast<Impl*>(data)->last_message = message ? message : "";
  }
};

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
  if (!(std::isfinite(options_.max_step) && options_.max_step >= 0.0))
    throw InputError("network integrator: max_step " + formatNumber(options_.max_step) + " must be >= 0");
  if (system_.size() == 0) throw InputError("network integrator: the system has no cells");
  Impl& m = *impl_;
  m.system = &system_;
  check(SUNContext_Create(nullptr, &m.context), "SUNContext_Create");
  const auto n = static_cast<sunindextype>(system_.size());
  m.y = N_VNew_Serial(n, m.context);
  if (!m.y) throw std::runtime_error("network integrator: N_VNew_Serial failed");
  m.J = system_.pattern();
  m.A = SUNSparseMatrix(n, n, static_cast<sunindextype>(std::max<std::size_t>(m.J.column.size(), 1)), CSR_MAT,
                        m.context);
  if (!m.A) throw std::runtime_error("network integrator: SUNSparseMatrix failed");
  m.solver = SUNLinSol_KLU(m.y, m.A, m.context);
  if (!m.solver) throw std::runtime_error("network integrator: SUNLinSol_KLU failed");
  // AMD: the Jacobian's pattern is symmetric (cell adjacency), where AMD fills in less than COLAMD.
  check(SUNLinSol_KLUSetOrdering(m.solver, 0), "SUNLinSol_KLUSetOrdering");
  m.cvode = CVodeCreate(CV_BDF, m.context);
  if (!m.cvode) throw std::runtime_error("network integrator: CVodeCreate failed");
  check(CVodeSetErrHandlerFn(m.cvode, &Impl::errorHandler, &m), "CVodeSetErrHandlerFn");
  check(CVodeInit(m.cvode, &Impl::rhs, 0.0, m.y), "CVodeInit");
  check(CVodeSetUserData(m.cvode, &m), "CVodeSetUserData");
  check(CVodeSStolerances(m.cvode, options_.relative_tolerance, options_.absolute_tolerance), "CVodeSStolerances");
  check(CVodeSetLinearSolver(m.cvode, m.solver, m.A), "CVodeSetLinearSolver");
  check(CVodeSetJacFn(m.cvode, &Impl::jac), "CVodeSetJacFn");
  check(CVodeSetMaxNumSteps(m.cvode, options_.max_steps), "CVodeSetMaxNumSteps");
  if (options_.max_step > 0) check(CVodeSetMaxStep(m.cvode, options_.max_step), "CVodeSetMaxStep");
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
  const int flag = CVode(m.cvode, t1, m.y, &t, CV_NORMAL);
  long v = 0;
  auto add = [&](int (*get)(void*, long*), long& total) {
    if (get(m.cvode, &v) >= 0) total += v;
  };
  add(CVodeGetNumSteps, stats_.steps);
  add(CVodeGetNumRhsEvals, stats_.rhs_evaluations);
  add(CVodeGetNumJacEvals, stats_.jacobian_evaluations);
  add(CVodeGetNumNonlinSolvIters, stats_.nonlinear_iterations);
  add(CVodeGetNumErrTestFails, stats_.error_test_failures);
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
    const std::size_t S = system_.numSpecies();
    const std::size_t cell = S ? worst / S : 0;
    const std::string& species = system_.model().species[S ? worst % S : 0].name;
    double reached = t;
    CVodeGetCurrentTime(m.cvode, &reached);
    std::ostringstream msg;
    msg << "network integration failed at t = " << formatNumber(reached) << " (integrating from "
        << formatNumber(t0) << " to " << formatNumber(t1) << "): CVODE " << flagName(flag);
    if (!m.last_message.empty()) msg << " (" << m.last_message << ")";
    msg << "; largest weighted local error in species '" << species << "' of cell " << cell << " ("
        << formatNumber(worst_value) << ")";
    throw NetworkIntegrationError(msg.str(), reached, flag, species, cell);
  }
  std::copy(state, state + y.size(), y.begin());
}

}  // namespace tessella::networks
