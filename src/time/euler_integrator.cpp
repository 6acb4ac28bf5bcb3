#include "rccm/time/euler_integrator.hpp"

#include "rccm/base/errors.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rccm {

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
  const Eigen::VectorXd beta_n = ode_.committed_beta();
  const double dt = t_new - ode_.committed_time();
  Eigen::VectorXd f(ode_.size()), J(ode_.size());
  ode_.rhs(t_new, beta_n, f);  // f at t_{n+1} with beta_n
  ode_.jacobian_diagonal(t_new, beta_n, J);
  ++stats_.rhs_evaluations;
  Eigen::VectorXd beta = beta_n + dt * f;
  for (int i = 0; i < ode_.size(); ++i) {
    max_ratio_ = std::max(max_ratio_, -dt * J[i]);
    if (beta[i] < 0) ++clamped_;
  }
  beta = beta.cwiseMax(0.0).cwiseMin(beta_n);  // the clamps counted above (warnings())
  ode_.accept(t_new, beta);
}

void EulerIntegrator::restore(const std::vector<double>& d) {
  RCCM_VERIFY(d.size() == 2, "Euler diagnostics: max ratio and clamped count");
  max_ratio_ = d[0];
  clamped_ = static_cast<long>(d[1]);
}

std::vector<std::string> EulerIntegrator::warnings() const {
  if (max_ratio_ <= 2 && clamped_ == 0) return {};
  std::ostringstream m;
  const bool unstable = max_ratio_ > 2;  // beta_{n+1} = beta_n (1 - ratio) + ...: stable for ratio < 2
  if (unstable)
    m << "explicit Euler was unstable: dt (Cn u_n^2 + Ct u_t^2) / alpha reached " << max_ratio_ << " (stable below 2)";
  else
    m << "explicit Euler overshot beta = 0: dt (Cn u_n^2 + Ct u_t^2) / alpha reached " << max_ratio_
      << " (above 1 a step passes beta = 0; stable below 2)";
  if (clamped_ > 0) m << (unstable ? " and" : ";") << " beta was clamped to 0 at " << clamped_ << " node-steps";
  m << "; beta is not time-accurate. Use integrator.method = \"arkode\" (its steps follow this ratio)";
  if (unstable)  // ratio < 1 neither oscillates nor overshoots; a lower bound: the ratio grows as nodes open
    m << ", or more than " << static_cast<long>(std::ceil(ode_.steps() * max_ratio_))
      << " steps (time.steps; rccm compare: --euler-steps), a lower bound: the ratio grows as nodes open";
  return {m.str()};
}

}  // namespace rccm
