#include "rccm/time/beta_ode.hpp"

#include "rccm/base/errors.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace rccm {

namespace {
double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

void SolveCounts::add(const ContactSolution& s, double solve_seconds) {
  ++contact_solves;
  seconds += solve_seconds;
  sweeps += s.iterations;
  max_sweeps = std::max(max_sweeps, s.iterations);
  timed_sweeps += s.timed_sweeps;
  threaded_sweeps += s.threaded_sweeps;
}

BetaOde::BetaOde(Model& model, std::unique_ptr<ContactSolver> solver, Observer observer)
    : model_(model),
      solver_(std::move(solver)),
      observer_(std::move(observer)),
      committed_(InterfaceState::initial(model)),
      step_start_(now()) {}

const ContactSolution& BetaOde::solve(double t, const Eigen::VectorXd& beta) {
  // The same (t, beta) again (an accepted step's solve, then the next step's first stage):
  // the same solution, also after the commit moved the slip reference onto it.
  if (t == last_t_ && beta == last_beta_) return last_;
  const double start = now();
  // Started from the latest solution (a nearby stage or, for the accepted step, the same
  // time), which is closer than the committed one. A stage value may leave [0, 1] by
  // round-off; the interface law is defined inside.
  const ContactSolution* from = last_t_ >= committed_.t ? &last_ : nullptr;
  try {
    last_ = solve_contact(model_, *solver_, t, beta.cwiseMax(0.0).cwiseMin(1.0), committed_, from);
  } catch (const SolveError& e) {
    throw SolveError("step " + std::to_string(step_ + 1) + ", " + e.what());
  }
  const double elapsed = now() - start;
  last_t_ = t;
  last_beta_ = beta;
  totals_.add(last_, elapsed);
  step_counts_.add(last_, elapsed);
  return last_;
}

void BetaOde::check_finite(double t, const Eigen::VectorXd& beta, const char* what) const {
  for (int i = 0; i < size(); ++i)
    if (!std::isfinite(beta[i])) {
      std::ostringstream m;
      m << "step " << step_ + 1 << ", t = " << t << " s: " << what << " beta at " << model_.locate(i) << " is "
        << beta[i] << ": the integrator diverged; tighten integrator.rtol or lower integrator.max_step";
      throw SolveError(m.str());
    }
}

std::vector<std::string> BetaOde::warnings() const {
  if (excursion_.size <= beta_slack) return {};
  std::ostringstream m;
  m << "the integrator gave beta outside [0, previous beta] by up to " << excursion_.size << " ("
    << model_.locate(excursion_.node) << ", t = " << excursion_.t << " s); it was clamped, and the damage there is not "
    << "time-accurate: tighten integrator.rtol or take more steps";
  return {m.str()};
}

void BetaOde::rhs(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> f) {
  // A stage value of beta may stray outside [0, 1] (a Newton iterate); the contact solve
  // uses it clamped, where the interface law is defined. NaN or Inf is a divergence.
  check_finite(t, beta, "the stage value of");
  const ContactSolution& s = solve(t, beta);
  const Interface& I = model_.interface();
  for (int i = 0; i < size(); ++i) f[i] = I.law(i).beta_rate(beta[i], I.layout.local(s.u, i));  // docs/MODEL.md s6
}

void BetaOde::jacobian_diagonal(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> J) {
  const ContactSolution& s = solve(t, beta);
  const Interface& I = model_.interface();
  for (int i = 0; i < size(); ++i) J[i] = I.law(i).beta_rate_derivative(beta[i], I.layout.local(s.u, i));
}

void BetaOde::rate_independent_beta(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> out) {
  check_finite(t, beta, "the iterate of");
  const ContactSolution& s = solve(t, beta);
  const Interface& I = model_.interface();
  for (int i = 0; i < size(); ++i)
    out[i] = I.law(i).rate_independent_beta(committed_.beta[i], I.layout.local(s.u, i));  // docs/MODEL.md s3
}

void BetaOde::resume(const InterfaceState& state, int step, const SolveCounts& totals, const Excursion& excursion,
                     const Eigen::VectorXd& springs_beta) {
  RCCM_VERIFY(state.beta.size() == size() && springs_beta.size() == size(), "checkpoint of another interface");
  committed_ = state;
  if (springs_beta != model_.springs_beta()) model_.condense(springs_beta);  // the checkpoint's y is of these springs
  step_ = step;
  totals_ = totals;
  excursion_ = excursion;
  last_t_ = -1;
}

void BetaOde::track_midpoints(std::unique_ptr<ContactSolver> solver) { midpoint_solver_ = std::move(solver); }

Eigen::VectorXd BetaOde::rate_at(const Eigen::VectorXd& beta, const Eigen::VectorXd& u) const {
  const Interface& I = model_.interface();
  Eigen::VectorXd f(size());
  for (int i = 0; i < size(); ++i) f[i] = I.law(i).beta_rate(beta[i], I.layout.local(u, i));
  return f;
}

InterfaceState BetaOde::midpoint(double t, const Eigen::VectorXd& beta, const ContactSolution& s) {
  const double h = t - committed_.t, t_mid = committed_.t + 0.5 * h;
  // Cubic Hermite at the middle: (b0 + b1)/2 + h (f0 - f1)/8, kept within [b1, b0] (beta falls).
  const Eigen::VectorXd f0 = rate_at(committed_.beta, committed_.u), f1 = rate_at(beta, s.u);
  const Eigen::VectorXd beta_mid =
      (0.5 * (committed_.beta + beta) + h / 8 * (f0 - f1)).cwiseMax(beta).cwiseMin(committed_.beta);
  const double start = now();
  ContactSolution mid;
  try {
    mid = solve_contact(model_, *midpoint_solver_, t_mid, beta_mid, committed_, &s);
  } catch (const SolveError& e) {
    throw SolveError("step " + std::to_string(step_ + 1) + ", the state halfway through it, " + e.what());
  }
  totals_.add(mid, now() - start);
  step_counts_.add(mid, now() - start);
  InterfaceState m;
  m.commit(t_mid, beta_mid, mid);
  return m;
}

void BetaOde::accept(double t, Eigen::Ref<Eigen::VectorXd> beta) {
  // beta in [0, 1] and never increasing (docs/MODEL.md s6): the scheme's round-off is
  // clamped; more than that is recorded for warnings(), a NaN or Inf stops the run.
  check_finite(t, beta, "the accepted");
  for (int i = 0; i < size(); ++i) {
    const double out = std::max(-beta[i], beta[i] - committed_.beta[i]);
    if (out > excursion_.size) excursion_ = {out, t, i};
  }
  beta = beta.cwiseMax(0.0).cwiseMin(committed_.beta);
  const double t_old = committed_.t;
  const ContactSolution& s = solve(t, beta);
  const ContactResiduals r = residuals(model_.contact_problem(t, beta, committed_.u), s);
  const bool with_midpoint = midpoint_solver_ && step_ >= 0 && t > committed_.t;
  if (with_midpoint) midpoint_ = midpoint(t, beta, s);
  committed_.commit(t, beta, s);
  ++step_;
  // Before the observer: the states it records are split for the K0 the run goes on with.
  if (model_.springs_lag(committed_.beta)) condense(model_.springs_following(committed_.beta));  // docs/MODEL.md s4
  const double clock = now();
  const AcceptedStep step{step_,       t, t - t_old, committed_, s, r, step_counts_, clock - step_start_,
                          with_midpoint ? &midpoint_ : nullptr};
  step_counts_ = SolveCounts{};
  step_start_ = clock;
  if (observer_) observer_(step);
}

void BetaOde::condense(const Eigen::VectorXd& springs_beta) {
  const double start = now();
  model_.condense(springs_beta);
  for (InterfaceState* s : {&committed_, &midpoint_}) {
    if (s->beta.size() == 0) continue;  // no midpoint tracked
    const ContactProblem pb = model_.contact_problem(s->t, s->beta, s->u);
    s->y = s->Rbar + (pb.Dref - pb.Dbeta).cwiseProduct(s->u);  // docs/MODEL.md s4
  }
  last_t_ = -1;
  solver_->forget_W0();
  if (midpoint_solver_) midpoint_solver_->forget_W0();
  ++totals_.condensations;
  totals_.condense_seconds += now() - start;
}

}  // namespace rccm
