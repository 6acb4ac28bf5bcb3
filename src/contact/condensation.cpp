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

Eigen::VectorXd Condensation::amplitudes(double t) const {
  Eigen::VectorXd a(amplitudes_.size());
  for (std::size_t k = 0; k < amplitudes_.size(); ++k) a[Eigen::Index(k)] = amplitudes_[k](t);
  return a;
}

Eigen::VectorXd Condensation::q0(double t) const { return Q_ * amplitudes(t); }

Eigen::VectorXd Condensation::displacement(double t, const Eigen::VectorXd& y) const {
  const Eigen::Index ndof = interface_.P.cols();
  return body_.solve(interface_.P.transpose() * y, Eigen::MatrixXd::Zero(ndof, 1)) + U_ * amplitudes(t);
}

Condensation::Forms Condensation::forms(const Eigen::MatrixXd& L) const {
  // u = K0^-1 P^T y + U a(t) (the first zero on the prescribed DOFs), so l.u = (P K0^-1 l).y + (U^T l).a.
  return {interface_.P * body_.solve(L, Eigen::MatrixXd::Zero(L.rows(), L.cols())), U_.transpose() * L};
}

}  // namespace rccm
