// The condensed interface problem at fixed beta (docs/MODEL.md s4):
//
//   u = W0 y + q0,   y = Rbar + E u,   E = Dref - D(beta),
//   D(beta) = a_i beta_i^2 (Ct, .., Cn) per pair,
//
// with W0 = P K0^-1 P^T the flexibility that already holds the springs Dref (D(1), or the
// springs at an earlier beta: Model::condense), and
// Rbar subject, pair by pair, to Signorini-Coulomb with mubar_i = mu (1 - beta_i), the gap
// g = g0 + u_n and the slip du_t = u_t - u_ref,t measured from the last accepted state.
// With Dref = D(beta) = 0 it is the plain frictional contact problem (W, q, mu) of Siconos.
#pragma once

#include "rccm/contact/delassus.hpp"
#include "rccm/interface/cone.hpp"
#include "rccm/interface/layout.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace rccm {

struct ContactProblem {
  Layout layout;
  const DelassusOperator* W0 = nullptr;  // flexibility, mm/N
  Eigen::VectorXd q0;                    // free response (interface forces zero), mm
  Eigen::VectorXd Dref, Dbeta;           // springs in W0's K0, and at beta; per component, N/mm
  Eigen::VectorXd mubar;                 // per pair
  Eigen::VectorXd g0;                    // initial gap per pair, mm
  Eigen::VectorXd u_ref;                 // last accepted u (its tangential parts: the slip reference), mm

  int size() const { return static_cast<int>(mubar.size()); }
  /// Pair i's local vector (du_t, g) at its local displacement u_i: its slip and its gap.
  LocalVector slip_and_gap(int i, const LocalVector& u_i) const;
};

struct ContactSolution {
  Eigen::VectorXd Rbar;  // contact + friction part of the reaction, N (local components per pair)
  Eigen::VectorXd u;     // interface displacement, mm
  Eigen::VectorXd y;     // Rbar + E u
  std::vector<Status> status;
  int iterations = 0;    // the solver's contact iterations: sweeps over all pairs (bipotential,
                         // rccm), Newton steps and fallback sweeps (newton)
  int exact_solves = 0;  // linear solves: exact active-set steps (bipotential), Newton directions
  int timed_sweeps = 0;     // bipotential sweeps of a compressed W0 (timed: la/thread_choice.hpp) ...
  int threaded_sweeps = 0;  // ... and of them those whose products several threads shared
  double residual = 0;   // largest scaled natural-map residual
  int worst_node = -1;   // pair of that residual
  bool converged = false;

  /// Adhesive part Radh = -D(beta) u (docs/MODEL.md s3).
  Eigen::VectorXd Radh(const ContactProblem& pb) const;
};

/// Residuals of the Signorini-Coulomb conditions, each relative to the problem's scale
/// (forces to the largest interface force, displacements to the largest |u|), and of the
/// condensed equilibrium u = W0 (Rbar + E u) + q0.
struct ContactResiduals {
  double equilibrium = 0;      // |W0 (Rbar + E u) + q0 - u| / max |u|
  double penetration = 0;      // max(0, -g)
  double tension = 0;          // max(0, -Rbar_n)
  double complementarity = 0;  // |g Rbar_n|
  double coulomb = 0;          // max(0, |Rbar_t| - mubar Rbar_n)
  double stick_slip = 0;       // |du_t| where |Rbar_t| < mubar Rbar_n (strictly inside)
  double slip_direction = 0;   // max(0, Rbar_t . du_t) at sliding pairs (friction must oppose slip)
  double max() const;
};

ContactResiduals residuals(const ContactProblem& pb, const ContactSolution& s);

/// The same problem with the springs folded in and the gap and slip shifts in q:
///   v = W R + q,  v = (u_t - u_ref,t, g0 + u_n),  W = (I - W0 E)^-1 W0,  q = (I - W0 E)^-1 q0 + shifts,
/// a plain frictional contact problem (W, q, mu) as Siconos and FCLIB pose it (docs/MODEL.md s4),
/// in the local order (tangential, normal). plain_form builds it dense (for checking against
/// a peer, not for production solves); a problem read from a file keeps the file's storage.
struct PlainContactProblem {
  int dim = 2;
  std::shared_ptr<const DelassusOperator> W;
  Eigen::VectorXd q, mu;
};
PlainContactProblem plain_form(const ContactProblem& pb);

/// A ContactProblem that poses `plain` (no springs, no gap, no previous slip); it points into it.
ContactProblem from_plain(const PlainContactProblem& plain);

}  // namespace rccm
