#include "rccm/interface/rccm_law.hpp"

#include <algorithm>

namespace rccm {

double RccmLaw::opening_energy(const LocalVector& u) const {
  const Eigen::Index n = u.size() - 1;
  double e = Cn * u[n] * u[n];
  for (Eigen::Index k = 0; k < n; ++k) e += Ct * u[k] * u[k];
  return e;
}

double RccmLaw::thermodynamic_force(double beta, const LocalVector& u) const {
  return w - opening_energy(u) * beta;
}

double RccmLaw::beta_rate(double beta, const LocalVector& u) const {
  return -std::max(0.0, -thermodynamic_force(beta, u)) / alpha;
}

double RccmLaw::beta_rate_derivative(double beta, const LocalVector& u) const {
  const double e = opening_energy(u);
  return e * beta > w ? -e / alpha : 0.0;
}

double RccmLaw::rate_independent_beta(double beta_max, const LocalVector& u) const {
  const double e = opening_energy(u);
  return e > 0 ? std::min(beta_max, w / e) : beta_max;
}

double RccmLaw::mubar(double beta) const { return mu * (1.0 - beta); }

LocalVector RccmLaw::spring(double a, int dim) const {
  LocalVector D = LocalVector::Constant(dim, a * Ct);
  D[dim - 1] = a * Cn;
  return D;
}

LocalVector RccmLaw::adhesive_force(double a, double beta, const LocalVector& u) const {
  const double s = -a * beta * beta;
  const Eigen::Index n = u.size() - 1;
  LocalVector R(u.size());
  for (Eigen::Index k = 0; k < n; ++k) R[k] = s * (Ct * u[k]);
  R[n] = s * (Cn * u[n]);
  return R;
}

double RccmLaw::free_energy(double beta, const LocalVector& u) const {
  return 0.5 * beta * beta * opening_energy(u) - w * beta;
}

}  // namespace rccm
