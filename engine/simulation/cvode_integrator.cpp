#include "simulation/cvode_integrator.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cstdlib>
#include <exception>
#include <string>
#include <utility>

namespace mx {

namespace {

[[noreturn]] void fail(const std::string& call, int flag, const std::string& detail) {
  std::string name = std::to_string(flag);
  if (char* text = CVodeGetReturnFlagName(flag)) {
    name = text;
    std::free(text);  // allocated by SUNDIALS with malloc
  }
  throw CvodeError("CVODE: " + call + " failed with " + name + (detail.empty() ? "" : ": " + detail));
}

template <class P>
P* require(P* pointer, const char* call) {
  if (pointer == nullptr) throw CvodeError(std::string("CVODE: ") + call + " returned null");
  return pointer;
}

}  // namespace

struct CvodeIntegrator::Impl {
  Rhs rhs;
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  N_Vector abstol = nullptr;
  void* memory = nullptr;
  SUNNonlinearSolver solver = nullptr;
  SUNMatrix matrix = nullptr;        // BDF only
  SUNLinearSolver linear = nullptr;  // BDF only
  double t = 0.0;
  std::exception_ptr rhs_error;
  std::string last_message;

  void check(int flag, const char* call) const {
    if (flag < 0) fail(call, flag, last_message);
  }

  ~Impl() {
    if (memory) CVodeFree(&memory);
    if (solver) SUNNonlinSolFree(solver);
    if (linear) SUNLinSolFree(linear);
    if (matrix) SUNMatDestroy(matrix);
    if (abstol) N_VDestroy(abstol);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
  }

  static int rhsCallback(realtype t, N_Vector y, N_Vector ydot, void* user) {
    auto* self = static_cast<Impl*>(user);
    // After a failure every call fails: CVODE may otherwise retry with smaller steps, forever.
    if (self->rhs_error) return -1;
    try {
      self->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
      return 0;
    } catch (...) {
      self->rhs_error = std::current_exception();
      return -1;  // unrecoverable: CVode returns CV_RHSFUNC_FAIL
    }
  }

  static void errorCallback(int, const char* module, const char* function, char* message, void* user) {
    static_cast<Impl*>(user)->last_message = std::string(module) + "::" + function + ": " + message;
  }
};

CvodeIntegrator::CvodeIntegrator(Rhs rhs, double t0, const std::vector<double>& y0, double rtol,
                                 const std::vector<double>& atol, long max_steps_per_call, Method method)
    : impl_(std::make_unique<Impl>()) {
  if (y0.empty() || atol.size() != y0.size())
    throw CvodeError("CVODE: the state must be non-empty with one atol per component");
  Impl& s = *impl_;
  s.rhs = std::move(rhs);
  s.t = t0;
  const auto n = static_cast<sunindextype>(y0.size());
  s.check(SUNContext_Create(nullptr, &s.context), "SUNContext_Create");
  s.y = require(N_VNew_Serial(n, s.context), "N_VNew_Serial");
  s.abstol = require(N_VNew_Serial(n, s.context), "N_VNew_Serial");
  for (sunindextype i = 0; i < n; ++i) {
    NV_Ith_S(s.y, i) = y0[static_cast<std::size_t>(i)];
    NV_Ith_S(s.abstol, i) = atol[static_cast<std::size_t>(i)];
  }
  s.memory = require(CVodeCreate(method == Method::Bdf ? CV_BDF : CV_ADAMS, s.context), "CVodeCreate");
  s.check(CVodeSetErrHandlerFn(s.memory, &Impl::errorCallback, &s), "CVodeSetErrHandlerFn");
  s.check(CVodeInit(s.memory, &Impl::rhsCallback, t0, s.y), "CVodeInit");
  s.check(CVodeSetUserData(s.memory, &s), "CVodeSetUserData");
  s.check(CVodeSVtolerances(s.memory, rtol, s.abstol), "CVodeSVtolerances");
  if (method == Method::Bdf) {
    // CVODE's default nonlinear solver is Newton; it needs a linear solver (Jacobian by difference quotients).
    s.matrix = require(SUNDenseMatrix(n, n, s.context), "SUNDenseMatrix");
    s.linear = require(SUNLinSol_Dense(s.y, s.matrix, s.context), "SUNLinSol_Dense");
    s.check(CVodeSetLinearSolver(s.memory, s.linear, s.matrix), "CVodeSetLinearSolver");
  } else {
    s.solver = require(SUNNonlinSol_FixedPoint(s.y, 0, s.context), "SUNNonlinSol_FixedPoint");
    s.check(CVodeSetNonlinearSolver(s.memory, s.solver), "CVodeSetNonlinearSolver");
  }
  s.check(CVodeSetMaxNumSteps(s.memory, max_steps_per_call), "CVodeSetMaxNumSteps");
}

CvodeIntegrator::~CvodeIntegrator() = default;

void CvodeIntegrator::advanceTo(double t) {
  Impl& s = *impl_;
  if (t == s.t) return;
  s.check(CVodeSetStopTime(s.memory, t), "CVodeSetStopTime");
  realtype reached = s.t;
  const int flag = CVode(s.memory, t, s.y, &reached, CV_NORMAL);
  if (s.rhs_error) std::rethrow_exception(std::exchange(s.rhs_error, nullptr));
  s.check(flag, "CVode");
  s.t = reached;
}

double CvodeIntegrator::time() const {
  return impl_->t;
}

const double* CvodeIntegrator::state() const {
  return N_VGetArrayPointer(impl_->y);
}

long CvodeIntegrator::steps() const {
  long count = 0;
  impl_->check(CVodeGetNumSteps(impl_->memory, &count), "CVodeGetNumSteps");
  return count;
}

}  // namespace mx
