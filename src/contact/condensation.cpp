#include "rccm/contact/condensation.hpp"

#include "rccm/contact/solver_tuning.hpp"

#include "rccm/base/errors.hpp"

#include <Eigen/LU>

namespace rccm {

namespace {

Eigen::MatrixXd unit_responses(const ElasticProblem& body, const std::vector<LoadCase>& loads, Eigen::Index ndof) {
  const Eigen::Index nl = static_cast<Eigen::Index>(loads.size());
  Eigen::MatrixXd f(ndof, nl), ud(ndof, nl);
  for (Eigen::Index k = 0; k < nl; ++k) {
    f.col(k) = loads[k].force;
    ud.col(k) = loads[k].displacement;
  }
  return body.solve(f, ud);
}

std::unique_ptr<DelassusOperator> flexibility(const ElasticProblem& body, const Interface& interface, bool compress) {
  if (!compress) return std::make_unique<DenseDelassus>(body.flexibility(interface.P));
  const auto products = [&](const Eigen::MatrixXd& Y) { return body.flexibility_products(interface.P, Y); };
  return std::make_unique<CompressedDelassus>(HodlrMatrix::symmetric(
      interface.P.rows(), products, tuning::hodlr_accuracy, tuning::hodlr_leaf, interface.layout.dim));
}

}  // namespace

Condensation::Condensation(const ElasticProblem& body, const Interface& interface, const std::vector<LoadCase>& loads,
                           bool compress_W0)
    : body_(body),
      interface_(interface),
      U_(unit_responses(body, loads, interface.P.cols())),
      Q_(interface.P * U_),
      W0_(flexibility(body, interface, compress_W0)) {
  for (const LoadCase& lc : loads) amplitudes_.push_back(lc.amplitude);
}

Eigen::VectorXd Condensation::amplitudes(double t) const {
  Eigen::VectorXd a(amplitudes_.size());
  for (std::size_t k = 0; k < amplitudes_.size(); ++k) a[Eigen::Index(k)] = amplitudes_[k](t);
  return a;
}

Eigen::VectorXd Condensation::q0(double t) const { return Q_ * amplitudes(t); }

Eigen::VectorXd Condensation::displacement(double t, const Eigen::VectorXd& y) const {
  const Eigen::Index ndof = interface_.P.cols();
  return body_.solve(interface_.P.transpose() * body_force(t, y), Eigen::MatrixXd::Zero(ndof, 1)) + U_ * amplitudes(t);
}

Eigen::VectorXd Condensation::body_force(double t, const Eigen::VectorXd& y) const {
  if (shift_.size() == 0) return y;
  Eigen::VectorXd u(y.size());
  W0_->multiply(y, u);
  return y + shift_.cwiseProduct(u + q0(t));  // y_K0 = Rbar + E_K0 u = y + (Dref_K0 - Dref) u
}

void Condensation::change_springs(const Eigen::VectorXd& dD) {
  const Eigen::Index m = W0_->size();
  RCCM_VERIFY(dD.size() == m, "change_springs(): one spring change per interface component");
  std::vector<Eigen::Index> S;
  for (Eigen::Index c = 0; c < m; ++c)
    if (dD[c] != 0) S.push_back(c);
  if (S.empty()) return;
  const Eigen::Index s = static_cast<Eigen::Index>(S.size());
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(m, s);
  for (Eigen::Index k = 0; k < s; ++k) unit(S[k], k) = 1;
  const Eigen::MatrixXd A = W0_->compressed() ? W0_->compressed()->multiply_block(unit) : *W0_->dense() * unit;
  Eigen::MatrixXd I_dW = Eigen::MatrixXd::Identity(s, s), dD_S = Eigen::MatrixXd::Zero(s, s), Q_S(s, Q_.cols());
  for (Eigen::Index k = 0; k < s; ++k) {
    dD_S(k, k) = dD[S[k]];
    I_dW.row(k) -= dD[S[k]] * A.row(S[k]);  // I - dD_S W0(S, S)
    Q_S.row(k) = Q_.row(S[k]);
  }
  Eigen::MatrixXd G = I_dW.partialPivLu().solve(dD_S);
  G = 0.5 * (G + G.transpose()).eval();  // symmetric but for round-off
  const Eigen::MatrixXd AG = A * G;
  Q_ += AG * Q_S;
  // The old W0 goes before the new one's other parts are built (the peak memory of a run).
  if (const Eigen::MatrixXd* W = W0_->dense()) {
    Eigen::MatrixXd Wc = *W + AG * A.transpose();
    W0_.reset();
    Wc = 0.5 * (Wc + Wc.transpose()).eval();
    W0_ = std::make_unique<DenseDelassus>(std::move(Wc));
  } else {
    HodlrMatrix Wc = W0_->compressed()->plus(AG, A, tuning::hodlr_accuracy);
    W0_.reset();
    W0_ = std::make_unique<CompressedDelassus>(std::move(Wc));
  }
  if (shift_.size() == 0) shift_ = Eigen::VectorXd::Zero(m);
  shift_ += dD;
}

Condensation::Forms Condensation::forms(const Eigen::MatrixXd& L) const {
  // u = K0^-1 P^T y + U a(t) (the first zero on the prescribed DOFs), so l.u = (P K0^-1 l).y + (U^T l).a.
  return {interface_.P * body_.solve(L, Eigen::MatrixXd::Zero(L.rows(), L.cols())), U_.transpose() * L};
}

}  // namespace rccm
