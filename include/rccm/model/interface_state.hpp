// The committed (last accepted) interface state and the contact solve that starts from it
// (docs/MODEL.md s6: slip increments relative to it, its reactions as warm start).
#pragma once

#include "rccm/contact/contact_solver.hpp"
#include "rccm/model/model.hpp"

#include <Eigen/Core>

#include <vector>

namespace rccm {

struct InterfaceState {
  double t = 0;
  Eigen::VectorXd beta;  // adhesion intensity per contact pair
  Eigen::VectorXd Rbar;  // contact + friction reaction (local components per pair), N
  Eigen::VectorXd u;     // interface displacement (local components per pair), mm
  Eigen::VectorXd y;     // Rbar + E u (to rebuild the bulk displacement)
  std::vector<Status> status;

  /// The state at t = 0 before any load: beta0, no force, no displacement.
  static InterfaceState initial(const Model& model);

  void commit(double time, const Eigen::VectorXd& new_beta, const ContactSolution& s);
};

/// One contact solve at (t, beta), slip measured from `committed`, iterations started from
/// `start` (default: the committed solution). Throws SolveError naming t, the worst pair and
/// what to change when it does not converge or the body comes loose.
ContactSolution solve_contact(const Model& model, ContactSolver& solver, double t, const Eigen::VectorXd& beta,
                              const InterfaceState& committed, const ContactSolution* start = nullptr);

}  // namespace rccm
