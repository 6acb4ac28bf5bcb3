// The Coulomb cone K_mubar = {|R_t| <= mubar R_n} of the bipotential method and the
// projection on it (docs/MODEL.md s5, paper eqs. 33-38), for a tangential part of one
// component (2D: the cone is a wedge) or two (3D: a circular cone). Written for any Eigen
// vector of a pair's local components: the run-time sized LocalVector, or the fixed-size
// vectors of the contact solvers' inner loops.
#pragma once

#include "rccm/interface/layout.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace rccm {

/// Branch of the projection on K_mubar: the status of a contact pair.
enum class Status { Separated, Stick, Slide };
const char* status_name(Status s);

/// sqrt(a^2 + b^2): the square root of the squares where they neither underflow nor overflow
/// (std::hypot, which guards both, took 8 % of a 3D run and a tenth of a small cold solve),
/// std::hypot beyond.
inline double hypot_fast(double a, double b) {
  a = std::abs(a), b = std::abs(b);
  const double big = std::max(a, b);
  return big > 1e-150 && big < 1e150 ? std::sqrt(a * a + b * b) : std::hypot(a, b);
}

/// |v_t|, the length of a local vector's tangential part (exactly |v_0| in 2D).
template <class V>
double tangential_norm(const Eigen::MatrixBase<V>& v) {
  return v.size() == 2 ? std::abs(v[0]) : hypot_fast(v[0], v[1]);
}

/// Which branch of the projection `tau` falls in (paper eqs. 38a-c).
template <class V>
Status cone_branch(const Eigen::MatrixBase<V>& tau, double mubar) {
  const double tau_t = tangential_norm(tau), tau_n = tau[tau.size() - 1];
  if (mubar * tau_t <= -tau_n) return Status::Separated;  // eq. 38a (polar cone)
  if (tau_t <= mubar * tau_n) return Status::Stick;       // eq. 38b
  return Status::Slide;                                   // eq. 38c
}

/// Projection of tau on K_mubar (docs/MODEL.md s5, paper eqs. 38a-c).
template <class V>
typename V::PlainObject project_cone(const Eigen::MatrixBase<V>& tau, double mubar) {
  const Eigen::Index n = tau.size() - 1;
  switch (cone_branch(tau, mubar)) {
    case Status::Separated: return V::PlainObject::Zero(tau.size());
    case Status::Stick: return tau;
    case Status::Slide: break;
  }
  // eq. 38c: the nearest point on the cone's surface, along tau_t (|tau_t| > 0 here).
  const double tau_t = tangential_norm(tau);
  const double Rn = (tau[n] + mubar * tau_t) / (1 + mubar * mubar);
  typename V::PlainObject R(tau.size());
  for (Eigen::Index k = 0; k < n; ++k) R[k] = mubar * Rn * (tau[k] / tau_t);
  R[n] = Rn;
  return R;
}

/// De Saxce's modified velocity (here: increment) s = (du_t, g + mubar |du_t|) of the
/// local vector v = (du_t, g): the slip increment and the gap (paper eq. 33).
template <class V>
typename V::PlainObject modified_velocity(const Eigen::MatrixBase<V>& v, double mubar) {
  typename V::PlainObject s = v;
  s[v.size() - 1] += mubar * tangential_norm(v);
  return s;
}

}  // namespace rccm
