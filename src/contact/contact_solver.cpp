#include "rccm/contact/contact_solver.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/contact/bipotential_solver.hpp"
#include "rccm/contact/newton_solver.hpp"
#include "rccm/contact/rccm_solver.hpp"

namespace rccm {

ContactSolution ContactSolver::solve(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                                     const Eigen::VectorXd& u_start) {
  const Eigen::Index m = pb.W0->size();
  RCCM_VERIFY(pb.q0.size() == m && pb.layout.offset(pb.size()) == m, "contact problem sizes");
  RCCM_VERIFY(pb.layout.dim == 2 || pb.layout.dim == 3, "contact pairs of 2 or 3 components");
  if (pb.q0.isZero(0.0)) {
    ContactSolution zero;
    zero.Rbar = zero.y = zero.u = Eigen::VectorXd::Zero(m);
    zero.status.assign(pb.size(), Status::Separated);
    zero.converged = true;
    return zero;
  }
  return solve_loaded(pb, Rbar_start, u_start);
}

std::unique_ptr<ContactSolver> make_contact_solver(const SolverParams& params) {
  switch (params.method) {
    case ContactMethod::Rccm: return std::make_unique<RccmSolver>(params);
    case ContactMethod::Newton: return std::make_unique<NewtonSolver>(params);
    case ContactMethod::Bipotential: break;
  }
  return std::make_unique<BipotentialSolver>(params);
}

}  // namespace rccm
