// The exact step of the bipotential solver (MODEL.md s5): once the status of every node
// repeats, the contact problem is linear,
//   separated  Rbar_i = 0,
//   stick      u_i = (ut_ref_i, -g0_i),
//   slide      u_n,i = -g0_i  and  Rbar_t,i = sign_i mubar_i Rbar_n,i,
// with u = W0 y + q0 and Rbar = y - E u in the unknown y. Its residual costs one product
// with W0. The system keeps an explicit inverse of the matrix of an earlier pattern and beta:
// the rows of the nodes whose status changed or whose beta moved (E, mubar) are folded into
// it by a rank-2c (Sherman-Morrison-Woodbury) update, 2 c m^2 operations instead of the
// 2 m^3 of a new factorization and inverse, and iterative refinement absorbs the small
// drift of the other rows. A new factorization only when refinement stalls or most rows changed.
#pragma once

#include "rccm/contact_problem.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace rccm {

/// Per node: which linear rows it contributes.
enum class Rows : std::int8_t { Free, Stick, SlidePositive, SlideNegative };

class ActiveSetSystem {
 public:
  /// Improves y towards the solution of the pattern's linear problem, with u = W0 y + q0
  /// given and kept in step. Returns false when the pattern's matrix is singular (the caller
  /// goes on sweeping).
  bool solve(const ContactProblem& pb, const std::vector<Rows>& pattern, Eigen::VectorXd& y, Eigen::VectorXd& u);

  int factorizations() const { return factorizations_; }
  const std::vector<Rows>& pattern() const { return factorized_; }  // of the factorized matrix

 private:
  Eigen::VectorXd residual(const ContactProblem& pb, const std::vector<Rows>& pattern, const Eigen::VectorXd& y,
                           const Eigen::VectorXd& u) const;
  Eigen::Matrix<double, 2, Eigen::Dynamic> rows(const ContactProblem& pb, Rows kind, int i) const;
  /// Whether node i's rows moved since they were factorized by more than refinement absorbs.
  bool rows_moved(const ContactProblem& pb, Rows kind, int i) const;
  /// Folds the changed nodes' rows into A0 and its inverse; false when a new factorization is due.
  bool update(const ContactProblem& pb, const std::vector<Rows>& pattern);
  /// A0 and its inverse afresh; false when A0 is singular.
  bool factorize(const ContactProblem& pb, const std::vector<Rows>& pattern);

  static constexpr double drift = 1e-3;  // relative row change left to refinement
  std::vector<Rows> factorized_;         // the pattern of A0_ (empty: none)
  Eigen::VectorXd E0_, mubar0_;          // the E = D1 - D(beta) and mubar of A0_'s rows
  Eigen::MatrixXd A0_, A0_inverse_;
  int factorizations_ = 0;
};

}  // namespace rccm
