#include "rccm/rccm_law.hpp"

#include <algorithm>
#include <cmath>

namespace rccm {

const char* status_name(Status s) {
  switch (s) {
    case Status::Separated: return "separated";
    case Status::Stick: return "stick";
    default: return "slide";
  }
}

Status cone_branch(const Vec2& tau, double mubar) {
  const double tau_t = std::abs(tau[0]), tau_n = tau[1];
  if (mubar * tau_t <= -tau_n) return Status::Separated;  // eq. 38a (polar cone)
  if (tau_t <= mubar * tau_n) return Status::Stick;       // eq. 38b
  return Status::Slide;                                   // eq. 38c
}

Vec2 project_cone(const Vec2& tau, double mubar) {
  switch (cone_branch(tau, mubar)) {
    case Status::Separated: return Vec2::Zero();
    case Status::Stick: return tau;
    default: {
      // eq. 38c: the nearest point on the ray R_t = mubar R_n sign(tau_t).
      const double Rn = (tau[1] + mubar * std::abs(tau[0])) / (1 + mubar * mubar);
      const double sign = tau[0] > 0 ? 1.0 : (tau[0] < 0 ? -1.0 : 0.0);
      return Vec2(mubar * Rn * sign, Rn);
    }
  }
}

Vec2 modified_velocity(double du_t, double gap, double mubar) {
  return Vec2(du_t, gap + mubar * std::abs(du_t));
}

Vec2 adhesive_force(double a, double beta, double Ct, double Cn, const Vec2& u) {
  return -a * beta * beta * Vec2(Ct * u[0], Cn * u[1]);
}

double thermodynamic_force(double beta, const Vec2& u, double Ct, double Cn, double w) {
  return w - (Cn * u[1] * u[1] + Ct * u[0] * u[0]) * beta;
}

double beta_rate(double beta, const Vec2& u, double Ct, double Cn, double w, double alpha) {
  return -std::max(0.0, -thermodynamic_force(beta, u, Ct, Cn, w)) / alpha;
}

double free_energy(double beta, const Vec2& u, double Ct, double Cn, double w) {
  return 0.5 * beta * beta * (Cn * u[1] * u[1] + Ct * u[0] * u[0]) - w * beta;
}

}  // namespace rccm
