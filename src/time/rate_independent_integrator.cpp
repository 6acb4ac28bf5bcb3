#include "rccm/time/rate_independent_integrator.hpp"

#include "rccm/base/errors.hpp"

#include <sstream>

namespace rccm {

void RateIndependentIntegrator::step(double t_new) {
  Eigen::VectorXd beta = ode_.committed_beta(), next(ode_.size()), last = Eigen::VectorXd::Zero(ode_.size());
  double relaxation = 1;  // of each update; halved at every oscillation of the iterates
  for (int k = 1;; ++k) {
    ode_.rate_independent_beta(t_new, beta, next);  // min(beta_n, w / (Cn u_n^2 + Ct u_t^2)) at u(beta)
    ++stats_.rhs_evaluations;
    ++stats_.newton_iterations;
    const Eigen::VectorXd update = next - beta;
    Eigen::Index node = 0;
    const double change = update.cwiseAbs().maxCoeff(&node);
    if (change <= tolerance_) {
      beta = next;
      break;
    }
    // A node whose update turned back: with friction a lower beta may stick (mubar grows) and
    // strain less, and the plain iteration can cycle around the consistent beta (slopes below
    // -1); relaxed, it contracts. Without friction the updates never turn back: plain.
    if ((update.array() * last.array() < 0 && update.array().abs() > tolerance_).any()) relaxation /= 2;
    beta += relaxation * update;
    last = update;
    if (k >= max_iterations_) {
      std::ostringstream m;
      m << "t = " << t_new << " s, step " << ode_.steps() + 1 << ": the rate-independent fixed point did not "
        << "converge in " << max_iterations_ << " iterations (change of beta " << change << " at "
        << ode_.locate(int(node)) << "); raise integrator.fixed_point_iterations or loosen integrator.fixed_point_tolerance ("
        << tolerance_ << ")";
      throw SolveError(m.str());
    }
  }
  ode_.accept(t_new, beta);
}

}  // namespace rccm
