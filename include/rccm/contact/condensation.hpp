// Elimination of the bulk onto the interface (docs/MODEL.md s4):
//   u_c = W0 y + q0(t),  W0 = P K0^-1 P^T,  q0(t) = sum_k amplitude_k(t) P U_k,
// where U_k is the displacement under load case k with the interface forces zero and the
// springs at beta = 1 (in K0). Built once per run: one CHOLMOD factorization, one solve per
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
};

}  // namespace rccm
