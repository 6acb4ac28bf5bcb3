#include "rccm/model/interface_state.hpp"

#include "rccm/base/errors.hpp"

#include <iomanip>
#include <sstream>

namespace rccm {

InterfaceState InterfaceState::initial(const Model& model) {
  InterfaceState s;
  const Eigen::Index m = model.interface().layout.offset(model.contact_nodes());
  s.beta = model.initial_beta();
  s.Rbar = s.u = s.y = Eigen::VectorXd::Zero(m);
  s.status.assign(model.contact_nodes(), Status::Separated);
  return s;
}

void InterfaceState::commit(double time, const Eigen::VectorXd& new_beta, const ContactSolution& s) {
  t = time;
  beta = new_beta;
  Rbar = s.Rbar;
  u = s.u;
  y = s.y;
  status = s.status;
}

ContactSolution solve_contact(const Model& model, ContactSolver& solver, double t, const Eigen::VectorXd& beta,
                              const InterfaceState& committed, const ContactSolution* start) {
  const ContactProblem pb = model.contact_problem(t, beta, committed.u);
  ContactSolution s;
  try {
    s = start ? solver.solve(pb, start->Rbar, start->u) : solver.solve(pb, committed.Rbar, committed.u);
  } catch (const SolveError& e) {
    std::ostringstream m;
    m << "t = " << t << " s: " << e.what();
    if (e.node >= 0) m << "; at " << model.locate(e.node);
    throw SolveError(m.str());
  }
  const long debonded = (beta.array() <= 0.0).count();
  // A displacement larger than the body itself (or not finite) is no small-strain solution:
  // the body has come loose (beta = 0 where the load pulls), whatever the residuals say.
  Eigen::Index worst = 0;
  const double umax = s.u.cwiseAbs().maxCoeff(&worst);
  if (!s.u.allFinite() || !s.Rbar.allFinite() || umax > model.size()) {
    std::ostringstream m;
    m << "t = " << t << " s: the interface displacement at " << model.locate(pb.layout.pairs(worst)) << " is "
      << std::setprecision(10) << umax << " mm, more than the body's size (" << model.size() << " mm)"
      << std::setprecision(6) << ": nothing holds the body there (" << debonded
      << " of " << beta.size() << " contact nodes have beta = 0); restrain it with a prescribed displacement, keep "
         "beta0 > 0, or reduce the load";
    throw SolveError(m.str());
  }
  if (!s.converged) {
    std::ostringstream m;
    m << "t = " << t << " s: the contact solve did not converge in " << s.iterations << " sweeps (scaled residual "
      << s.residual << " at " << model.locate(s.worst_node) << "; " << debonded << " of " << beta.size()
      << " contact nodes have beta = 0";
    if (2 * debonded > beta.size()) m << ": the body may no longer be held";
    m << "); " << solver.failure_advice();
    throw SolveError(m.str());
  }
  return s;
}

}  // namespace rccm
