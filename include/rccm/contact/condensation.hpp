// Elimination of the bulk onto the interface (docs/MODEL.md s4):
//   u_c = W0 y + q0(t),  W0 = P K0^-1 P^T,  q0(t) = sum_k amplitude_k(t) P U_k,
// where U_k is the displacement under load case k with the interface forces zero and the
// springs at beta = 1 (in K0); W0 and q0 follow later changes of a few pairs' springs
// without a new factorization (change_springs). Built once per run: one CHOLMOD factorization, one solve per
// load case, and W0 either dense from the factor's trailing block (the interface DOFs ordered
// last) or, on large interfaces, compressed from blocks of sparse solves without ever being
// formed (contact/delassus.hpp).
#pragma once

#include "rccm/contact/delassus.hpp"
#include "rccm/fem/elastic_problem.hpp"
#include "rccm/fem/loads.hpp"
#include "rccm/interface/interface.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace rccm {

class Condensation {
 public:
  /// `compress_W0`: W0 compressed from sparse solves, never dense (the body's factor may then
  /// be ordered freely); otherwise dense (the interface DOFs ordered last in the factor).
  Condensation(const ElasticProblem& body, const Interface& interface, const std::vector<LoadCase>& loads,
               bool compress_W0);

  const DelassusOperator& W0() const { return *W0_; }

  /// Free response at time t, mm.
  Eigen::VectorXd q0(double t) const;

  /// Full nodal displacement at time t under the interface force y = Rbar + E u_c.
  Eigen::VectorXd displacement(double t, const Eigen::VectorXd& y) const;

  /// W0 and the load responses for W0's springs lowered by dD (one entry per interface
  /// component, zero but on the few pairs that change; negative stiffens), without a new
  /// factorization of K0: with S the components that change and A = W0(:, S), Woodbury's
  /// formula (docs/MODEL.md s4)
  ///   W0' = W0 + A G A^T,  Q' = Q + A G Q(S, :),  G = (I - dD_S W0(S, S))^-1 dD_S,
  /// about m^2 s work (dense) or a recompression of each block (compressed), s = |S|.
  /// K0 keeps its springs: the body takes the force body_force(t, y).
  void change_springs(const Eigen::VectorXd& dD);
  /// The interface's force on K0's body when W0's splitting has the force y at time t:
  /// y + (K0's springs - W0's) u_c, with u_c = W0 y + q0(t) (y itself until change_springs).
  Eigen::VectorXd body_force(double t, const Eigen::VectorXd& y) const;

  /// Linear functionals l.u of the full displacement, one per column of L (all DOFs), condensed:
  /// l.u = g.y + h.a(t), with g = P K0^-1 l (l on the free DOFs) and h_k = l.U_k. One block solve.
  struct Forms {
    Eigen::MatrixXd g, h;  // one column per functional
  };
  Forms forms(const Eigen::MatrixXd& L) const;
  /// The loads' amplitudes a_k(t).
  Eigen::VectorXd amplitudes(double t) const;

 private:
  const ElasticProblem& body_;
  const Interface& interface_;
  std::vector<TimeFunction> amplitudes_;
  Eigen::MatrixXd U_;  // full displacement of each unit load case (columns)
  Eigen::MatrixXd Q_;  // P U_k (columns)
  std::unique_ptr<DelassusOperator> W0_;
  Eigen::VectorXd shift_;  // K0's springs - W0's, per interface component (change_springs)
};

}  // namespace rccm
