#include "rccm/time/rate_independent_integrator.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/format.hpp"

#include <sstream>

namespace rccm {

void RateIndependentIntegrator::step(double t_new) {
  Eigen::VectorXd beta = ode_.committed_beta(), next(ode_.size()), last = Eigen::VectorXd::Zero(ode_.size());
  Eigen::ArrayXd relaxation = Eigen::ArrayXd::Ones(ode_.size()), halved = relaxation;  // of each node's update
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
    // A node whose update turned back without halving: with friction a lower beta may stick
    // (mubar grows) and strain less, and the plain iteration can cycle around the consistent
    // beta (slopes below -1); relaxed, it contracts. Turns also come and go in a cascade
    // (B1 snapping through, with or without friction), where the plain iteration converges:
    // a node is relaxed only from its third such turn on, by a factor halved at each turn
    // since the first. Node by node, so that an unzipping front elsewhere keeps full steps.
    const auto cycling = update.array() * last.array() < 0 && update.array().abs() > 0.5 * last.array().abs() &&
                         update.array().abs() > tolerance_;
    turns += cycling.cast<int>();
    halved = cycling.select((halved / 2).max(1.0 / 1024), halved);  // contracts slopes down to -2047
    relaxation = (turns >= 3).select(halved, 1.0);
    beta.array() += relaxation * update.array();
    last = update;
    if (k >= max_iterations_) {
      std::ostringstream m;
      m << "t = " << t_new << " s, step " << ode_.steps() + 1 << ": the rate-independent fixed point did not "
        << "converge in " << max_iterations_ << " iterations (change of beta " << change << " at "
        << ode_.locate(int(node)) << "); raise integrator.fixed_point_iterations or loosen integrator.fixed_point_tolerance ("
        << tolerance_ << ")" << (relaxation.minCoeff() < 1 ? "; its updates cycled and were relaxed down to " + fmt("%g", relaxation.minCoeff()) + " (friction: a node that sticks as beta falls)" : "");
      throw SolveError(m.str());
    }
  }
  ode_.accept(t_new, beta);
}

}  // namespace rccm
