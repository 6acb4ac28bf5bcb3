#include "rccm/time/arkode_integrator.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/la/parallel.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_dirk.h>
#include <arkode/arkode_butcher_erk.h>
#include <nvector/nvector_parallel.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>
#include <exception>
#include <numeric>
#include <sstream>
#include <vector>

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

}  // namespace

// ARKODE's state: in one process all of beta (NVECTOR_SERIAL) and the modified Newton's
// diagonal Jacobian solved by KLU. Under mpirun with several processes each holds a contiguous
// slice of the contact pairs (NVECTOR_PARALLEL: ARKODE's norms and dot products are reduced
// over the processes); the contact problem stays replicated, so each callback gathers the whole
// beta, evaluates the BetaSystem on it (the one contact solve every process does) and keeps
// its own slice of the result. KLU takes no parallel vector: there the diagonal Newton matrix
// I - gamma J is solved by GMRES preconditioned by its exact inverse (one iteration), J v from
// the same diagonal (a difference quotient would cost a contact solve per product).
struct ArkodeIntegrator::Impl {
  BetaSystem& ode;
  const bool distributed = parallel::size() > 1;
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

  // The pairs of each process's slice of the state, [firsts[p], firsts[p] + counts[p]) (one
  // process: all of them), as the vectors hold them; this process's are [first, first + count).
  std::vector<int> counts, firsts;
  int first = 0, count = 0;
  Eigen::VectorXd whole, whole_f, whole_d;  // beta of all pairs gathered, f and df/dbeta there
  Eigen::VectorXd diagonal;                 // df_i/dbeta_i of this process's pairs: the Newton matrix

  Impl(BetaSystem& o, const IntegratorParams& p, double T) : ode(o), scheme(p.scheme), fixed_step(p.fixed_step) {
    const sunindextype n = ode.size();
    whole_f.resize(n);
    whole_d.resize(n);
    check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
    y = new_state();
    local(y) = ode.committed_beta().segment(first, count);
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
      attach_newton_solver();
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

  /// ARKODE's state vector, and the slices: all pairs in one process; under mpirun a balanced
  /// contiguous slice on each, the slices' sizes then taken from the vectors of all processes.
  N_Vector new_state() {
    const int n = ode.size();
    if (!distributed) {
      counts = {n};
      firsts = {0};
      count = n;
      return check_ptr(N_VNew_Serial(n, ctx), "N_VNew_Serial");
    }
    const int processes = parallel::size(), rank = parallel::rank();
    const int mine = n / processes + (rank < n % processes ? 1 : 0);
    N_Vector v = check_ptr(N_VNew_Parallel(MPI_COMM_WORLD, mine, n, ctx), "N_VNew_Parallel");
    count = static_cast<int>(N_VGetLocalLength_Parallel(v));
    counts.assign(processes, 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    firsts.assign(processes, 0);
    for (int k = 1; k < processes; ++k) firsts[k] = firsts[k - 1] + counts[k - 1];
    first = firsts[rank];
    return v;
  }

  /// The implicit stages' linear solver for the Newton matrix I - gamma J, J = diag(df_i/dbeta_i).
  void attach_newton_solver() {
    if (!distributed) {
      const sunindextype n = ode.size();
      J = check_ptr(SUNSparseMatrix(n, n, n, CSC_MAT, ctx), "SUNSparseMatrix");
      LS = check_ptr(SUNLinSol_KLU(y, J, ctx), "SUNLinSol_KLU");
      check(ARKStepSetLinearSolver(mem, LS, J), "ARKStepSetLinearSolver");
      check(ARKStepSetJacFn(mem, jacobian), "ARKStepSetJacFn");
      return;
    }
    // ARKODE hands the preconditioner's set-up the same "J is still good" decisions as KLU's
    // Jacobian function above (arkLsSetup): the same modified Newton.
    LS = check_ptr(SUNLinSol_SPGMR(y, SUN_PREC_RIGHT, 0, ctx), "SUNLinSol_SPGMR");
    check(ARKStepSetLinearSolver(mem, LS, nullptr), "ARKStepSetLinearSolver");
    check(ARKStepSetPreconditioner(mem, precondition, precondition_solve), "ARKStepSetPreconditioner");
    check(ARKStepSetJacTimes(mem, nullptr, jacobian_times), "ARKStepSetJacTimes");
  }

  /// This process's part of an ARKODE vector.
  Eigen::Map<Eigen::VectorXd> local(N_Vector v) const { return {N_VGetArrayPointer(v), count}; }

  /// The whole beta of which `v` holds this process's slice (every process must call it).
  Eigen::VectorXd& gather(N_Vector v) {
    if (!distributed) return whole = local(v);
    whole.resize(ode.size());
    MPI_Allgatherv(N_VGetArrayPointer(v), count, MPI_DOUBLE, whole.data(), counts.data(), firsts.data(), MPI_DOUBLE,
                   MPI_COMM_WORLD);
    return whole;
  }

  /// df_i/dbeta_i at (t, beta) for this process's pairs.
  void evaluate_diagonal(realtype t, N_Vector beta) {
    ode.jacobian_diagonal(t, gather(beta), whole_d);
    diagonal = whole_d.segment(first, count);
  }

  /// A callback's work, its outcome said as ARKODE wants it: 0, `on_solve_error` when a contact
  /// solve failed (1: recoverable, ARKODE cuts the step), -1 for anything else, kept to be
  /// rethrown after ARKODE returns (nothing may unwind through its C frames). Under mpirun the
  /// worst outcome of all processes: each takes ARKODE's same path, none is left waiting in a
  /// gather for one that left (a write failing on process 0 alone).
  template <class Work>
  int guarded(int on_solve_error, Work&& work) {
    int flag = 0;
    try {
      work();
    } catch (const WriteError&) {  // a full disk (a SolveError, so caught first): said as it is, not as ARKODE's
      stop = std::current_exception();
      flag = -1;
    } catch (const SolveError& e) {
      contact_failure = e.what();
      flag = on_solve_error;
    } catch (...) {
      stop = std::current_exception();
      flag = -1;
    }
    return distributed ? -parallel::largest(-flag) : flag;
  }

  static int rhs(realtype t, N_Vector beta, N_Vector f, void* data) {
    auto* self = static_cast<Impl*>(data);
    return self->guarded(1, [&] {
      self->ode.rhs(t, self->gather(beta), self->whole_f);
      self->local(f) = self->whole_f.segment(self->first, self->count);
    });
  }

  static int jacobian(realtype t, N_Vector beta, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(data);
    return self->guarded(1, [&] {
      self->evaluate_diagonal(t, beta);
      const Eigen::VectorXd& d = self->diagonal;
      sunindextype* col = SUNSparseMatrix_IndexPointers(J);
      sunindextype* row = SUNSparseMatrix_IndexValues(J);
      realtype* value = SUNSparseMatrix_Data(J);
      for (sunindextype i = 0; i < d.size(); ++i) col[i] = row[i] = i, value[i] = d[i];
      col[d.size()] = d.size();
    });
  }

  static int precondition(realtype t, N_Vector beta, N_Vector, booleantype jok, booleantype* jcur, realtype, void* data) {
    auto* self = static_cast<Impl*>(data);
    *jcur = !jok;
    if (jok) return 0;  // the diagonal kept (jok is the same on every process: ARKODE's counts)
    return self->guarded(1, [&] { self->evaluate_diagonal(t, beta); });
  }

  /// z = (I - gamma J)^-1 r: exact, J being diagonal (df_i/dbeta_i <= 0: 1 - gamma J_ii >= 1).
  static int precondition_solve(realtype, N_Vector, N_Vector, N_Vector r, N_Vector z, realtype gamma, realtype, int,
                                void* data) {
    auto* self = static_cast<Impl*>(data);
    self->local(z) = self->local(r).array() / (1.0 - gamma * self->diagonal.array());
    return 0;
  }

  static int jacobian_times(N_Vector v, N_Vector Jv, realtype, N_Vector, N_Vector, void* data, N_Vector) {
    auto* self = static_cast<Impl*>(data);
    self->local(Jv) = self->diagonal.cwiseProduct(self->local(v));
    return 0;
  }

  static int accepted(realtype t, N_Vector beta, void* data) {
    auto* self = static_cast<Impl*>(data);
    return self->guarded(-1, [&] {
      Eigen::VectorXd& b = self->gather(beta);
      self->ode.accept(t, b);  // clamps b
      self->local(beta) = b.segment(self->first, self->count);
    });
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
  s.rejected = m.counter(ARKStepGetNumErrTestFails) + m.counter(ARKStepGetNumStepSolveFails);
  long nfe = 0, nfi = 0;
  ARKStepGetNumRhsEvals(m.mem, &nfe, &nfi);
  s.rhs_evaluations = nfe + nfi;
  s.newton_iterations = m.counter(ARKStepGetNumNonlinSolvIters);
  if (m.distributed)
    s.slices = {static_cast<int>(m.counts.size()), *std::min_element(m.counts.begin(), m.counts.end()),
                *std::max_element(m.counts.begin(), m.counts.end()), std::accumulate(m.counts.begin(), m.counts.end(), 0)};
  return s;
}

}  // namespace rccm
