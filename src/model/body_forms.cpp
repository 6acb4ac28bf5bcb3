#include "rccm/model/body_forms.hpp"

namespace rccm {

LoadWork operator+(const LoadWork& x, const LoadWork& y) { return {x.a + y.a, x.phi + y.phi, x.rho + y.rho}; }
LoadWork operator-(const LoadWork& x, const LoadWork& y) { return {x.a - y.a, x.phi - y.phi, x.rho - y.rho}; }
LoadWork operator-(const LoadWork& x) { return {-x.a, -x.phi, -x.rho}; }
LoadWork operator*(double c, const LoadWork& x) { return {c * x.a, c * x.phi, c * x.rho}; }
LoadWork operator/(const LoadWork& x, double c) { return {x.a / c, x.phi / c, x.rho / c}; }
double dot(const LoadWork& x, const LoadWork& y) { return x.a.dot(y.phi) + y.a.dot(x.rho); }

BodyForms::BodyForms(const Condensation& condensation, const SparseMatrix& K, const Interface& interface,
                     const std::vector<LoadCase>& loads, const std::vector<char>& free, const Mesh& mesh,
                     const std::vector<int>& probes)
    : condensation_(condensation), loads_(static_cast<int>(loads.size())), applied_(Eigen::VectorXd::Zero(loads_)) {
  const Eigen::Index ndof = K.rows(), columns = per_load * loads_ + mesh.dim * Eigen::Index(probes.size());
  // The functionals on u (L) and on r (R, as -R^T P^T r = -(P R)^T r) of each figure.
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(ndof, columns), R = Eigen::MatrixXd::Zero(ndof, columns);
  for (int k = 0; k < loads_; ++k) {
    const LoadCase& lc = loads[k];
    const Eigen::Index first = per_load * k;
    for (Eigen::Index d = 0; d < ndof; ++d)
      if (free[d]) L(d, first) = lc.force[d];  // phi_k = f_k . u (free DOFs)
    L.col(first + 1) = K * lc.displacement;       // rho_k = ud_k . (K u - P^T r)
    R.col(first + 1) = lc.displacement;
    const Eigen::VectorXd along = lc.direction(ndof);
    if (lc.reaction) {  // the supports' reaction along it: along . (K u - P^T r)
      L.col(first + 2) = K * along;
      R.col(first + 2) = along;
    } else {  // what it applies: a_k along . f_k
      applied_[k] = along.dot(lc.force);
    }
    L.col(first + 3) = along / double(lc.nodes);
  }
  for (std::size_t p = 0; p < probes.size(); ++p)
    for (int c = 0; c < mesh.dim; ++c) L(mesh.dof(probes[p], c), per_load * loads_ + mesh.dim * Eigen::Index(p) + c) = 1;
  Condensation::Forms f = condensation.forms(L);
  g_ = std::move(f.g);
  h_ = std::move(f.h);
  c_ = interface.P * R;
}

BodyResultants BodyForms::evaluate(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& r) const {
  const Eigen::VectorXd a = condensation_.amplitudes(t);
  const Eigen::VectorXd v = g_.transpose() * condensation_.body_force(t, y) + h_.transpose() * a - c_.transpose() * r;
  BodyResultants b;
  b.work = {a, Eigen::VectorXd(loads_), Eigen::VectorXd(loads_)};
  for (int k = 0; k < loads_; ++k) {
    const Eigen::Index first = per_load * k;
    b.work.phi[k] = v[first];
    b.work.rho[k] = v[first + 1];
    b.force.push_back(v[first + 2] + a[k] * applied_[k]);
    b.displacement.push_back(v[first + 3]);
  }
  for (Eigen::Index j = per_load * loads_; j < v.size(); ++j) b.probes.push_back(v[j]);
  return b;
}

}  // namespace rccm
