#include "rccm/time/arkode_integrator.hpp"

#include "rccm/base/errors.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_dirk.h>
#include <arkode/arkode_butcher_erk.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>
#include <exception>
#include <sstream>

namespace rccm {

namespace {

/// Every SUNDIALS call's flag is checked with the function's name (SUNDIALS examples' style).
void check(int flag, const char* function) {
  if (flag < 0) throw InternalError(std::string(function) + " failed with flag " + std::to_string(flag));
}

template <class T>
T* check_ptr(T* p, const char* function) {
  if (!p) throw InternalError(std::string(function) + " returned NULL");
  return p;
}

Eigen::Map<Eigen::VectorXd> as_eigen(N_Vector v) {
  return {N_VGetArrayPointer(v), N_VGetLength(v)};
}

}  // namespace

struct ArkodeIntegrator::Impl {
  BetaSystem& ode;
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  SUNMatrix J = nullptr;
  SUNLinearSolver LS = nullptr;
  void* mem = nullptr;
  std::string contact_failure;  // the last contact solve that failed, for the final message
  std::string arkode_message;   // ARKODE's own last error message
  std::exception_ptr stop;       // what a callback caught that is no contact failure (a stop request, a failed write, a bug)

  ArkodeScheme scheme;
  double fixed_step;  // > 0: ARKODE takes it without error control, its Newton failures cannot cut it

  Impl(BetaSystem& o, const IntegratorParams& p, double T) : ode(o), scheme(p.scheme), fixed_step(p.fixed_step) {
    const sunindextype n = ode.size();
    check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
    y = check_ptr(N_VNew_Serial(n, ctx), "N_VNew_Serial");
    as_eigen(y) = ode.committed_beta();
    const bool implicit = p.scheme == ArkodeScheme::Dirk;
    mem = check_ptr(ARKStepCreate(implicit ? nullptr : rhs, implicit ? rhs : nullptr, ode.committed_time(), y, ctx),
                    "ARKStepCreate");
    check(ARKStepSetUserData(mem, this), "ARKStepSetUserData");
    check(ARKStepSetErrHandlerFn(mem, error_handler, this), "ARKStepSetErrHandlerFn");
    check(ARKStepSStolerances(mem, p.rtol, p.atol), "ARKStepSStolerances");
    check(ARKStepSetMaxStep(mem, p.largest_step(T)), "ARKStepSetMaxStep");
    if (p.initial_step > 0) check(ARKStepSetInitStep(mem, p.initial_step), "ARKStepSetInitStep");
    if (p.fixed_step > 0) check(ARKStepSetFixedStep(mem, p.fixed_step), "ARKStepSetFixedStep");
    // A collapsing step (a nearly unrestrained body, a discontinuous f) fails instead of crawling.
    check(ARKStepSetMinStep(mem, p.min_step > 0 ? p.min_step : 1e-9 * T), "ARKStepSetMinStep");
    check(ARKStepSetMaxNumSteps(mem, p.max_steps), "ARKStepSetMaxNumSteps");
    check(ARKStepSetPostprocessStepFn(mem, accepted), "ARKStepSetPostprocessStepFn");
    // No ARKStepSetConstraints(beta >= 0): near beta ~ w / (C u^2) ~ 1e-9 it cut steps until
    // ARKODE gave up (alpha = 0.01); BetaOde::accept clamps beta to [0, committed] instead.
    // DIRK: the 4th-order ESDIRK of ARK4(3)6L (explicit first stage, stiffly accurate,
    // L-stable) by default; on B1 it needs 4x fewer contact solves than ARKODE's default
    // SDIRK_5_3_4 for the same error in beta (docs/PERFORMANCE.md "The contact step and the integrator").
    const std::string table = !p.table.empty() ? p.table : implicit ? IntegratorParams::default_dirk_table : "";
    if (!table.empty())
      check(ARKStepSetTableName(mem, implicit ? table.c_str() : "ARKODE_DIRK_NONE",
                                implicit ? "ARKODE_ERK_NONE" : table.c_str()),
            "ARKStepSetTableName");
    if (implicit) {
      J = check_ptr(SUNSparseMatrix(n, n, n, CSC_MAT, ctx), "SUNSparseMatrix");
      LS = check_ptr(SUNLinSol_KLU(y, J, ctx), "SUNLinSol_KLU");
      check(ARKStepSetLinearSolver(mem, LS, J), "ARKStepSetLinearSolver");
      check(ARKStepSetJacFn(mem, jacobian), "ARKStepSetJacFn");
      // The Newton matrix I - gamma J is rebuilt every step (the step size and the active set
      // of the max(0, .) change); J itself is evaluated again after a Newton
      // failure and at least every 51 steps (ARKODE's default). On B1, J every step measured
      // no better: 7635 contact solves against 7553.
      check(ARKStepSetLSetupFrequency(mem, 1), "ARKStepSetLSetupFrequency");
      // Each f is a contact solve: Newton starts from the interpolant of the last step
      // (predictor 1, half the Newton iterations of the trivial predictor on B1), and the
      // stage's f is deduced from its Newton solution instead of solved once more.
      check(ARKStepSetPredictorMethod(mem, 1), "ARKStepSetPredictorMethod");
      check(ARKStepSetDeduceImplicitRhs(mem, SUNTRUE), "ARKStepSetDeduceImplicitRhs");
    }
  }

  ~Impl() {
    ARKStepFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (J) SUNMatDestroy(J);
    N_VDestroy(y);
    SUNContext_Free(&ctx);
  }

  static int rhs(realtype t, N_Vector beta, N_Vector f, void* data) {
    auto* self = static_cast<Impl*>(data);
    try {
      self->ode.rhs(t, as_eigen(beta), as_eigen(f));
      return 0;
    } catch (const SolveError& e) {
      self->contact_failure = e.what();
      return 1;  // recoverable: ARKODE retries with a smaller step
    } catch (...) {  // nothing may unwind through ARKODE's C frames: rethrown after it returns
      self->stop = std::current_exception();
      return -1;
    }
  }

  static int jacobian(realtype t, N_Vector beta, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(data);
    try {
      Eigen::VectorXd d(self->ode.size());
      self->ode.jacobian_diagonal(t, as_eigen(beta), d);
      sunindextype* col = SUNSparseMatrix_IndexPointers(J);
      sunindextype* row = SUNSparseMatrix_IndexValues(J);
      realtype* value = SUNSparseMatrix_Data(J);
      for (sunindextype i = 0; i < d.size(); ++i) col[i] = row[i] = i, value[i] = d[i];
      col[d.size()] = d.size();
      return 0;
    } catch (const SolveError& e) {
      self->contact_failure = e.what();
      return 1;
    } catch (...) {
      self->stop = std::current_exception();
      return -1;
    }
  }

  static int accepted(realtype t, N_Vector beta, void* data) {
    auto* self = static_cast<Impl*>(data);
    try {
      self->ode.accept(t, as_eigen(beta));
      return 0;
    } catch (const WriteError&) {  // a full disk (a SolveError, so caught first): said as it is, not as ARKODE's
      self->stop = std::current_exception();
      return -1;
    } catch (const SolveError& e) {
      self->contact_failure = e.what();
      return -1;
    } catch (...) {
      self->stop = std::current_exception();
      return -1;
    }
  }

  static void error_handler(int, const char* module, const char* function, char* msg, void* data) {
    static_cast<Impl*>(data)->arkode_message = std::string(module) + "::" + function + ": " + msg;
  }

  long counter(int (*get)(void*, long*)) const {
    long v = 0;
    get(mem, &v);
    return v;
  }
};

bool arkode_table_exists(bool implicit, const std::string& name) {
  // ARKODE reports an unknown name on stderr itself; the config reader says it with the
  // file and line, so stderr is closed for the look-up.
  std::fflush(stderr);
  const int saved = ::dup(2), null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) ::dup2(null, 2);
  ARKodeButcherTable B =
      implicit ? ARKodeButcherTable_LoadDIRKByName(name.c_str()) : ARKodeButcherTable_LoadERKByName(name.c_str());
  std::fflush(stderr);
  if (saved >= 0) ::dup2(saved, 2), ::close(saved);
  if (null >= 0) ::close(null);
  if (!B) return false;
  ARKodeButcherTable_Free(B);
  return true;
}

ArkodeIntegrator::ArkodeIntegrator(BetaSystem& ode, const IntegratorParams& params, double T)
    : impl_(std::make_unique<Impl>(ode, params, T)) {}

ArkodeIntegrator::~ArkodeIntegrator() = default;

void ArkodeIntegrator::advance(double t_out) {
  Impl& m = *impl_;
  check(ARKStepSetStopTime(m.mem, t_out), "ARKStepSetStopTime");
  realtype t = m.ode.committed_time();
  const int flag = ARKStepEvolve(m.mem, t_out, m.y, &t, ARK_NORMAL);
  if (flag >= 0) return;
  if (m.stop) std::rethrow_exception(m.stop);

  std::ostringstream msg;
  char* name = ARKStepGetReturnFlagName(flag);  // malloc'ed by ARKODE
  msg << "ARKODE stopped at t = " << m.ode.committed_time() << " s after step " << m.ode.steps() << " (" << name
      << ", flag " << flag << ")";
  std::free(name);
  if (!m.arkode_message.empty()) msg << ": " << m.arkode_message;
  if (!m.contact_failure.empty()) msg << "\n  last contact failure: " << m.contact_failure;
  const Eigen::VectorXd& beta = m.ode.committed_beta();
  const bool adhesion_gone = 2 * (beta.array() < 1e-3).count() > beta.size();
  msg << "\n  state: min beta " << beta.minCoeff() << ", " << (beta.array() < 1e-3).count() << " of " << beta.size()
      << " contact nodes with beta < 1e-3";
  if (adhesion_gone) msg << ": most adhesion is gone and the body may be nearly free (held by forces ~ beta^2 C u)";
  if (flag == ARK_TOO_MUCH_WORK)
    msg << "\n  raise integrator.max_steps"
        << (m.scheme == ArkodeScheme::Erk ? ", or use scheme = \"dirk\" (an explicit scheme on this stiff ODE needs tiny steps)"
                                           : ", or loosen integrator.rtol");
  else if (flag == ARK_REPTD_RHSFUNC_ERR || flag == ARK_UNREC_RHSFUNC_ERR)
    msg << "\n  ARKODE cut its step and the contact solve still failed: see the contact failure above";
  else if ((flag == ARK_ERR_FAILURE || flag == ARK_CONV_FAILURE) && m.fixed_step > 0)
    msg << "\n  the fixed step integrator.fixed_step = " << m.fixed_step << " s is too long for the Newton iteration "
        << "of its stages here (a fixed step is not cut): take a smaller one, or leave it 0 (adaptive steps)";
  else if ((flag == ARK_ERR_FAILURE || flag == ARK_CONV_FAILURE) && adhesion_gone)
    msg << "\n  the step size collapsed as the adhesion went: the body may be nearly free; restrain it, reduce the "
           "load, or lower integrator.min_step";
  else if (flag == ARK_ERR_FAILURE || flag == ARK_CONV_FAILURE)
    msg << "\n  the step size collapsed (beta or the contact state changes abruptly here): lower integrator.min_step, "
           "loosen integrator.rtol, or check the interface parameters for extreme values";
  else
    msg << "\n  loosen integrator.rtol/atol, lower integrator.max_step, or see the contact failure above";
  throw SolveError(msg.str());
}

double ArkodeIntegrator::last_step() const {
  realtype h = 0;
  ARKStepGetLastStep(impl_->mem, &h);
  return h;
}

IntegratorStats ArkodeIntegrator::stats() const {
  const Impl& m = *impl_;
  IntegratorStats s;
  s.steps = m.counter(ARKStepGetNumSteps);
  s.rejected = m.counter(ARKStepGetNumErrTestFails) + m.counter(ARKStepGetNumNonlinSolvConvFails);
  long nfe = 0, nfi = 0;
  ARKStepGetNumRhsEvals(m.mem, &nfe, &nfi);
  s.rhs_evaluations = nfe + nfi;
  s.newton_iterations = m.counter(ARKStepGetNumNonlinSolvIters);
  return s;
}

}  // namespace rccm
