#include "rccm/euler_integrator.hpp"

#include "rccm/errors.hpp"

#include <cmath>
#include <sstream>

namespace rccm {

EulerIntegrator::EulerIntegrator(BetaOde& ode, const Config& cfg)
    : FixedStepIntegrator(ode, cfg), alpha_(cfg.interface.alpha) {}

void EulerIntegrator::step(double t_new) {
  try {
    take_step(t_new);
  } catch (const SolveError& e) {
    std::string msg = e.what();
    for (const std::string& w : warnings()) msg += "\n  note: " + w;
    throw SolveError(msg);
  }
}

void EulerIntegrator::take_step(double t_new) {
  const InterfaceState& c = ode_.committed();
  const double dt = t_new - c.t;
  Eigen::VectorXd f(ode_.size());
  const ContactSolution& s = ode_.rhs(t_new, c.beta, f);  // contact at t_{n+1} with beta_n
  ++stats_.rhs_evaluations;
  const Eigen::VectorXd e = ode_.opening_energy(s);
  Eigen::VectorXd beta = c.beta + dt * f;
  for (int i = 0; i < ode_.size(); ++i) {
    if (f[i] < 0) max_ratio_ = std::max(max_ratio_, dt * e[i] / alpha_);
    if (beta[i] < 0) ++clamped_;
  }
  beta = beta.cwiseMax(0.0).cwiseMin(c.beta);  // the clamps counted above (warnings())
  ode_.accept(t_new, beta);                    // re-solves and commits
}

void EulerIntegrator::restore(const std::vector<double>& d) {
  RCCM_VERIFY(d.size() == 2, "Euler diagnostics: max ratio and clamped count");
  max_ratio_ = d[0];
  clamped_ = static_cast<long>(d[1]);
}

std::vector<std::string> EulerIntegrator::warnings() const {
  if (max_ratio_ <= 2 && clamped_ == 0) return {};
  std::ostringstream m;
  m << "explicit Euler was unstable: dt (Cn u_n^2 + Ct u_t^2) / alpha reached " << max_ratio_
    << " (stable below 2)";
  if (clamped_ > 0) m << " and beta was clamped to 0 at " << clamped_ << " node-steps";
  m << "; beta is not time-accurate. Use integrator.method = \"arkode\", or at least "
    << static_cast<long>(std::ceil(ode_.steps() * max_ratio_ / 2)) << " steps (time.steps)";
  return {m.str()};
}

}  // namespace rccm
