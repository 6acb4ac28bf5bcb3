#include "rccm/contact/contact_problem.hpp"

#include "rccm/base/errors.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace rccm {

LocalVector ContactProblem::slip_and_gap(int i, const LocalVector& u_i) const {
  LocalVector v = u_i;
  v.head(layout.tangential_size()) -= layout.tangential(u_ref, i);
  v[layout.dim - 1] += g0[i];
  return v;
}

Eigen::VectorXd ContactSolution::Radh(const ContactProblem& pb) const { return -pb.Dbeta.cwiseProduct(u); }

double ContactResiduals::max() const {
  return std::max({equilibrium, penetration, tension, complementarity, coulomb, stick_slip, slip_direction});
}

ContactResiduals residuals(const ContactProblem& pb, const ContactSolution& s) {
  const Layout& L = pb.layout;
  const Eigen::VectorXd r = s.Rbar + s.Radh(pb);
  const double F = std::max({s.Rbar.cwiseAbs().maxCoeff(), r.cwiseAbs().maxCoeff(), 1e-300});
  const double U = std::max({s.u.cwiseAbs().maxCoeff(), pb.g0.cwiseAbs().maxCoeff(), 1e-300});
  ContactResiduals c;
  const Eigen::VectorXd y = s.Rbar + (pb.Dref - pb.Dbeta).cwiseProduct(s.u);
  Eigen::VectorXd Wy(y.size());
  if (const Eigen::MatrixXd* W0 = pb.W0->dense())
    Wy.noalias() = *W0 * y;  // not by a compression the solver used: an independent check
  else
    pb.W0->multiply(y, Wy);
  c.equilibrium = (Wy + pb.q0 - s.u).cwiseAbs().maxCoeff() / U;
  for (int i = 0; i < pb.size(); ++i) {
    const LocalVector R = L.local(s.Rbar, i), v = pb.slip_and_gap(i, L.local(s.u, i));
    const Eigen::Index n = L.dim - 1;
    const double Rt = tangential_norm(R), Rn = R[n], g = v[n], du = tangential_norm(v);
    const double limit = pb.mubar[i] * Rn;
    c.penetration = std::max(c.penetration, -g / U);
    c.tension = std::max(c.tension, -Rn / F);
    c.complementarity = std::max(c.complementarity, std::abs(g * Rn) / (U * F));
    c.coulomb = std::max(c.coulomb, (Rt - limit) / F);
    // Strictly inside the cone (with a margin for round-off): no slip.
    if (Rt < limit - 1e-6 * F) c.stick_slip = std::max(c.stick_slip, du / U);
    // On the boundary: slip opposes the friction force (Rbar_t . du_t <= 0).
    double Rt_du = 0;
    for (Eigen::Index k = 0; k < n; ++k) Rt_du += R[k] * v[k];
    if (Rn > 1e-6 * F) c.slip_direction = std::max(c.slip_direction, Rt_du / (F * U));
  }
  return c;
}

PlainContactProblem plain_form(const ContactProblem& pb) {
  const Eigen::MatrixXd* W0 = pb.W0->dense();
  RCCM_VERIFY(W0 != nullptr, "the plain form needs a dense W0");
  const Eigen::Index m = W0->rows();
  const Eigen::VectorXd E = pb.Dref - pb.Dbeta;
  const Eigen::PartialPivLU<Eigen::MatrixXd> A(Eigen::MatrixXd::Identity(m, m) - (*W0) * E.asDiagonal());
  const Eigen::MatrixXd W = A.solve(*W0);
  PlainContactProblem p{pb.layout.dim, std::make_shared<DenseDelassus>(0.5 * (W + W.transpose())), A.solve(pb.q0),
                        pb.mubar};
  for (int i = 0; i < pb.size(); ++i) {
    pb.layout.tangential(p.q, i) -= pb.layout.tangential(pb.u_ref, i);
    p.q[pb.layout.normal(i)] += pb.g0[i];
  }
  return p;
}

ContactProblem from_plain(const PlainContactProblem& plain) {
  ContactProblem pb;
  const Eigen::Index n = plain.mu.size();
  pb.layout.dim = plain.dim;
  pb.W0 = plain.W.get();
  pb.q0 = plain.q;
  pb.Dref = pb.Dbeta = Eigen::VectorXd::Zero(plain.dim * n);
  pb.mubar = plain.mu;
  pb.g0 = Eigen::VectorXd::Zero(n);
  pb.u_ref = Eigen::VectorXd::Zero(plain.dim * n);
  return pb;
}

}  // namespace rccm
