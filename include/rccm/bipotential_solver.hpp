// The bipotential contact solver of De Saxce and Feng at fixed beta (MODEL.md s5):
// node-wise Uzawa predictor-corrector,
//   tau = Rbar - rho_i s_i(u),   Rbar = proj(tau, K_mubar)      (paper eqs. 35-38)
// on the condensed problem of ContactProblem. The adhesive spring stays inside the
// node-wise solve (a 2x2 matter), so a change of beta costs nothing global.
#pragma once

#include "rccm/active_set.hpp"
#include "rccm/config.hpp"
#include "rccm/contact_problem.hpp"

namespace rccm {

class BipotentialSolver {
 public:
  explicit BipotentialSolver(const SolverParams& params) : params_(params) {}

  /// Solves `pb` starting from a previous (Rbar, u) (empty vectors: from zero).
  /// Never throws for non-convergence: check `converged` (and `worst_node`).
  /// Throws SolveError when a node has no stiffness left (an unrestrained structure).
  ContactSolution solve(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start = {},
                        const Eigen::VectorXd& u_start = {}) const;

  const SolverParams& params() const { return params_; }

 private:
  SolverParams params_;
  // The exact step's factorization, reused while the status pattern repeats from one solve
  // to the next (a cache: results do not depend on it beyond the tolerance).
  mutable ActiveSetSystem active_set_;
};

}  // namespace rccm
