#include "rccm/contact_problem.hpp"

#include <algorithm>
#include <cmath>

namespace rccm {

Eigen::VectorXd ContactSolution::Radh(const ContactProblem& pb) const {
  return -pb.Dbeta.cwiseProduct(u);
}

double ContactResiduals::max() const {
  return std::max({equilibrium, penetration, tension, complementarity, coulomb, stick_slip, slip_direction});
}

ContactResiduals residuals(const ContactProblem& pb, const ContactSolution& s) {
  const Eigen::VectorXd r = s.Rbar + s.Radh(pb);
  const double F = std::max({s.Rbar.cwiseAbs().maxCoeff(), r.cwiseAbs().maxCoeff(), 1e-300});
  const double U = std::max({s.u.cwiseAbs().maxCoeff(), pb.g0.cwiseAbs().maxCoeff(), 1e-300});
  ContactResiduals c;
  const Eigen::VectorXd y = s.Rbar + (pb.D1 - pb.Dbeta).cwiseProduct(s.u);
  c.equilibrium = ((*pb.W0) * y + pb.q0 - s.u).cwiseAbs().maxCoeff() / U;
  for (int i = 0; i < pb.size(); ++i) {
    const double Rt = s.Rbar[2 * i], Rn = s.Rbar[2 * i + 1];
    const double g = pb.g0[i] + s.u[2 * i + 1], du = s.u[2 * i] - pb.ut_ref[i];
    const double limit = pb.mubar[i] * Rn;
    c.penetration = std::max(c.penetration, -g / U);
    c.tension = std::max(c.tension, -Rn / F);
    c.complementarity = std::max(c.complementarity, std::abs(g * Rn) / (U * F));
    c.coulomb = std::max(c.coulomb, (std::abs(Rt) - limit) / F);
    // Strictly inside the cone (with a margin for round-off): no slip.
    if (std::abs(Rt) < limit - 1e-6 * F) c.stick_slip = std::max(c.stick_slip, std::abs(du) / U);
    // On the boundary: slip opposes the friction force.
    if (Rn > 1e-6 * F) c.slip_direction = std::max(c.slip_direction, Rt * du / (F * U));
  }
  return c;
}

}  // namespace rccm
