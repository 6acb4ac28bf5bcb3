#include "rccm/interface_state.hpp"

#include "rccm/errors.hpp"

#include <algorithm>
#include <sstream>

namespace rccm {

InterfaceState InterfaceState::initial(const Model& model) {
  InterfaceState s;
  const int m = 2 * model.contact_nodes();
  s.beta = model.initial_beta();
  s.Rbar = Eigen::VectorXd::Zero(m);
  s.u = Eigen::VectorXd::Zero(m);
  s.y = Eigen::VectorXd::Zero(m);
  s.status.assign(model.contact_nodes(), Status::Separated);
  return s;
}

Eigen::VectorXd InterfaceState::ut() const {
  return Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2>>(u.data(), u.size() / 2);
}

void InterfaceState::commit(double time, const Eigen::VectorXd& new_beta, const ContactSolution& s) {
  t = time;
  beta = new_beta;
  Rbar = s.Rbar;
  u = s.u;
  y = s.y;
  status = s.status;
}

ContactSolution solve_contact(const Model& model, const BipotentialSolver& solver, double t,
                              const Eigen::VectorXd& beta, const InterfaceState& committed,
                              const ContactSolution* start) {
  const ContactProblem pb = model.contact_problem(t, beta, committed.ut());
  ContactSolution s;
  try {
    s = start ? solver.solve(pb, start->Rbar, start->u) : solver.solve(pb, committed.Rbar, committed.u);
  } catch (const SolveError& e) {
    std::ostringstream m;
    m << "t = " << t << " s: " << e.what();
    throw SolveError(m.str());
  }
  // A displacement larger than the body itself (or not finite) is no small-strain solution:
  // the body has come loose (beta = 0 where the load pulls), whatever the residuals say.
  const double size = std::max(model.config().mesh.size[0], model.config().mesh.size[1]);
  Eigen::Index worst = 0;
  const double umax = s.u.cwiseAbs().maxCoeff(&worst);
  if (!s.u.allFinite() || !s.Rbar.allFinite() || umax > size) {
    std::ostringstream m;
    const long debonded = (beta.array() <= 0.0).count();
    m << "t = " << t << " s: the interface displacement at contact node " << worst / 2 << " is " << umax
      << " mm, more than the body's size (" << size << " mm): nothing holds the body there (" << debonded << " of "
      << beta.size() << " contact nodes have beta = 0); restrain it with a prescribed displacement, keep beta0 > 0, "
         "or reduce the load";
    throw SolveError(m.str());
  }
  if (!s.converged) {
    std::ostringstream m;
    const long debonded = (beta.array() <= 0.0).count();
    m << "t = " << t << " s: the contact solve did not converge in " << solver.params().max_iterations
      << " sweeps (scaled residual " << s.residual << " at contact node " << s.worst_node << "; " << debonded
      << " of " << beta.size() << " contact nodes have beta = 0";
    if (2 * debonded > beta.size()) m << ": the body may no longer be held";
    m << "); ";
    if (solver.params().form == SweepForm::Jacobi)
      m << "the Jacobi form diverges on strongly coupled interfaces: use solver.form = \"gauss-seidel\" "
        << "or under-relax it (solver.relaxation = 0.2 works on B2)";
    else
      m << "raise solver.max_iterations, loosen solver.tolerance (" << solver.params().tolerance
        << ") or take smaller steps";
    throw SolveError(m.str());
  }
  return s;
}

}  // namespace rccm
