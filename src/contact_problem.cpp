#include "rccm/contact_problem.hpp"

#include <Eigen/Dense>

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

namespace rccm {

PlainContactProblem plain_form(const ContactProblem& pb) {
  const Eigen::MatrixXd& W0 = *pb.W0;
  const Eigen::Index m = W0.rows();
  const Eigen::VectorXd E = pb.D1 - pb.Dbeta;
  const Eigen::PartialPivLU<Eigen::MatrixXd> A(Eigen::MatrixXd::Identity(m, m) - W0 * E.asDiagonal());
  PlainContactProblem p;
  p.W = A.solve(W0);
  p.W = 0.5 * (p.W + p.W.transpose()).eval();
  p.q = A.solve(pb.q0);
  for (int i = 0; i < pb.size(); ++i) {
    p.q[2 * i] -= pb.ut_ref[i];
    p.q[2 * i + 1] += pb.g0[i];
  }
  p.mu = pb.mubar;
  return p;
}

ContactProblem from_plain(const PlainContactProblem& plain) {
  ContactProblem pb;
  const Eigen::Index n = plain.mu.size();
  pb.W0 = &plain.W;
  pb.q0 = plain.q;
  pb.D1 = pb.Dbeta = Eigen::VectorXd::Zero(2 * n);
  pb.mubar = plain.mu;
  pb.g0 = pb.ut_ref = Eigen::VectorXd::Zero(n);
  return pb;
}

}  // namespace rccm
