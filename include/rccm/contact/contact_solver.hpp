// A solver of the condensed contact problem at fixed beta (contact_problem.hpp). Every
// integrator stage performs one solve, warm-started from a nearby solution.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/contact/contact_problem.hpp"

#include <memory>
#include <string>

namespace rccm {

class ContactSolver {
 public:
  virtual ~ContactSolver() = default;

  /// Solves `pb` starting from a nearby solution's (Rbar, u) (empty vectors: from zero).
  /// Never throws for non-convergence: check `converged` (and `worst_node`). Throws SolveError
  /// when a pair has no stiffness left (an unrestrained structure). Without load (q0 = 0, e.g.
  /// t = 0) the solution is exactly zero, without iterating: from a warm start Rbar would
  /// shrink geometrically while its relative change stays constant.
  ContactSolution solve(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start, const Eigen::VectorXd& u_start);

  /// W0 changed (the model was condensed anew, Model::condense): what a solver kept of the
  /// old one (a factorization, an inverse) must not serve the new one.
  virtual void forget_W0() = 0;
  /// For the message of a solve that did not converge: what to change.
  virtual std::string failure_advice() const = 0;

 protected:
  /// The solve of a loaded problem of pairs of 2 or 3 components, sizes checked.
  virtual ContactSolution solve_loaded(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                                       const Eigen::VectorXd& u_start) = 0;
};

/// The contact solver the config asks for (solver.method and its settings).
std::unique_ptr<ContactSolver> make_contact_solver(const SolverParams& params);

}  // namespace rccm
