#include "rccm/time/rate_independent_integrator.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/format.hpp"

#include <sstream>

namespace rccm {

void RateIndependentIntegrator::step(double t_new) {
  Eigen::VectorXd beta = ode_.committed_beta(), next(ode_.size()), last = Eigen::VectorXd::Zero(ode_.size());
  Eigen::ArrayXd relaxation = Eigen::ArrayXd::Ones(ode_.size());  // of each node's update
  Eigen::ArrayXi turns = Eigen::ArrayXi::Zero(ode_.size());
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
    // A node whose update turns back without halving: with friction a lower beta may stick
    // (mubar grows) and strain less, and the plain iteration can cycle around the consistent
    // beta (slopes below -1); relaxed, it contracts. A few such turns also come and go in a
    // snap-through cascade (B1, with or without friction), where the plain iteration converges:
    // a node's relaxation is halved only from its third such turn on (1/2 at the third).
    // Node by node, so that an unzipping front elsewhere keeps full steps.
    const auto cycling = update.array() * last.array() < 0 && update.array().abs() > 0.5 * last.array().abs() &&
                         update.array().abs() > tolerance_;
    turns += cycling.cast<int>();
    relaxation = (cycling && turns >= 3).select((relaxation / 2).max(1.0 / 1024), relaxation);  // contracts slopes down to -2047
    beta.array() += relaxation * update.array();
    last = update;
    if (k >= max_iterations_) {
      std::ostringstream m;
      m << "t = " << t_new << " s, step " << ode_.steps() + 1 << ": the rate-independent fixed point did not "
        << "converge in " << max_iterations_ << " iterations (change of beta " << change << " at "
        << ode_.locate(int(node)) << "); raise integrator.fixed_point_iterations or loosen integrator.fixed_point_tolerance ("
        << tolerance_ << ")" << (relaxation.minCoeff() < 1 ? "; updates that kept turning back were relaxed down to " + fmt("%g", relaxation.minCoeff()) + " (with friction: a node that sticks as beta falls)" : "");
      throw SolveError(m.str());
    }
  }
  ode_.accept(t_new, beta);
}

}  // namespace rccm
