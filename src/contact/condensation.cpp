#include "rccm/contact/condensation.hpp"

#include "rccm/contact/solver_tuning.hpp"

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

Eigen::VectorXd Condensation::q0(double t) const {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(Q_.rows());
  for (std::size_t k = 0; k < amplitudes_.size(); ++k) q += amplitudes_[k](t) * Q_.col(k);
  return q;
}

Eigen::VectorXd Condensation::displacement(double t, const Eigen::VectorXd& y) const {
  const Eigen::Index ndof = interface_.P.cols();
  Eigen::VectorXd u = body_.solve(interface_.P.transpose() * y, Eigen::MatrixXd::Zero(ndof, 1));
  for (std::size_t k = 0; k < amplitudes_.size(); ++k) u += amplitudes_[k](t) * U_.col(k);
  return u;
}

}  // namespace rccm
