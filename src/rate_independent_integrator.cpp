#include "rccm/rate_independent_integrator.hpp"

#include "rccm/errors.hpp"

#include <sstream>

namespace rccm {

RateIndependentIntegrator::RateIndependentIntegrator(BetaOde& ode, const Config& cfg)
    : FixedStepIntegrator(ode, cfg),
      w_(cfg.interface.w),
      tolerance_(cfg.integrator.fixed_point_tolerance),
      max_iterations_(cfg.integrator.fixed_point_iterations) {}

void RateIndependentIntegrator::step(double t_new) {
  const Eigen::VectorXd beta_old = ode_.committed().beta;
  Eigen::VectorXd beta = beta_old, f(ode_.size());
  for (int k = 1;; ++k) {
    const ContactSolution& s = ode_.rhs(t_new, beta, f);
    ++stats_.rhs_evaluations;
    ++stats_.newton_iterations;
    const Eigen::VectorXd e = ode_.opening_energy(s);
    Eigen::VectorXd next = beta_old;
    for (int i = 0; i < ode_.size(); ++i)
      if (e[i] > 0) next[i] = std::min(beta_old[i], w_ / e[i]);  // MODEL.md s3, alpha -> 0
    Eigen::Index node = 0;
    const double change = (next - beta).cwiseAbs().maxCoeff(&node);
    beta = next;
    if (change <= tolerance_) break;
    if (k >= max_iterations_) {
      std::ostringstream m;
      m << "t = " << t_new << " s, step " << ode_.steps() + 1 << ": the rate-independent fixed point did not "
        << "converge in " << max_iterations_ << " iterations (change of beta " << change << " at contact node "
        << node << "); raise integrator.fixed_point_iterations or take smaller steps (time.steps)";
      throw SolveError(m.str());
    }
  }
  ode_.accept(t_new, beta);
}

}  // namespace rccm
