#include "rccm/time/rate_independent_integrator.hpp"

#include "rccm/base/errors.hpp"

#include <sstream>

namespace rccm {

void RateIndependentIntegrator::step(double t_new) {
  Eigen::VectorXd beta = ode_.committed_beta(), next(ode_.size());
  for (int k = 1;; ++k) {
    ode_.rate_independent_beta(t_new, beta, next);
    ++stats_.rhs_evaluations;
    ++stats_.newton_iterations;
    Eigen::Index node = 0;
    const double change = (next - beta).cwiseAbs().maxCoeff(&node);
    beta = next;
    if (change <= tolerance_) break;
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
