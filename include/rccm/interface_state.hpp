// The committed (last accepted) interface state and the contact solve that starts from it
// (MODEL.md s6: slip increments relative to it, its reactions as warm start).
#pragma once

#include "rccm/bipotential_solver.hpp"
#include "rccm/model.hpp"

#include <Eigen/Core>

namespace rccm {

struct InterfaceState {
  double t = 0;
  Eigen::VectorXd beta;  // adhesion intensity per contact node
  Eigen::VectorXd Rbar;  // contact + friction reaction (t, n per node), N
  Eigen::VectorXd u;     // interface displacement (t, n per node), mm
  Eigen::VectorXd y;     // Rbar + E u (to rebuild the bulk displacement)
  std::vector<Status> status;

  /// The state at t = 0 before any load: beta0, no force, no displacement.
  static InterfaceState initial(const Model& model);

  /// Tangential displacement of each node (the reference of the next slip increment).
  Eigen::VectorXd ut() const;

  void commit(double time, const Eigen::VectorXd& new_beta, const ContactSolution& s);
};

/// One contact solve at (t, beta), slip measured from `committed`, iterations started from
/// `start` (default: the committed solution). Throws SolveError naming t, the worst node and
/// what to change when it does not converge.
ContactSolution solve_contact(const Model& model, const BipotentialSolver& solver, double t,
                              const Eigen::VectorXd& beta, const InterfaceState& committed,
                              const ContactSolution* start = nullptr);

}  // namespace rccm
