// The exact step of the bipotential solver (MODEL.md s5): once the status of every node
// repeats, the contact problem is linear,
//   separated  Rbar_i = 0,
//   stick      u_i = (ut_ref_i, -g0_i),
//   slide      u_n,i = -g0_i  and  Rbar_t,i = sign_i mubar_i Rbar_n,i,
// with u = W0 y + q0 and Rbar = y - E u in the unknown y. Its residual costs one product
// with W0; its matrix is factorized only when many nodes change. In between, the rows of the
// few nodes whose status changed or whose beta moved (E, mubar) are replaced exactly by a
// low-rank (Sherman-Morrison-Woodbury) update, and iterative refinement absorbs the rest.
#pragma once

#include "rccm/contact_problem.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

#include <cstdint>
#include <vector>

namespace rccm {

/// Per node: which linear rows it contributes.
enum class Rows : std::int8_t { Free, Stick, SlidePositive, SlideNegative };

class ActiveSetSystem {
 public:
  /// Improves y towards the solution of the pattern's linear problem. Returns false when
  /// the pattern's matrix is singular (the caller goes on sweeping).
  bool solve(const ContactProblem& pb, const std::vector<Rows>& pattern, Eigen::VectorXd& y);

  int factorizations() const { return factorizations_; }
  const std::vector<Rows>& pattern() const { return factorized_; }  // of the factorization

 private:
  Eigen::VectorXd residual(const ContactProblem& pb, const std::vector<Rows>& pattern, const Eigen::VectorXd& y) const;
  Eigen::Matrix<double, 2, Eigen::Dynamic> rows(const ContactProblem& pb, Rows kind, int i) const;
  Eigen::MatrixXd matrix(const ContactProblem& pb, const std::vector<Rows>& pattern) const;
  bool prepare_update(const ContactProblem& pb, const std::vector<Rows>& pattern);
  /// Whether node i's rows moved since the factorization by more than refinement absorbs.
  bool rows_moved(const ContactProblem& pb, Rows kind, int i) const;
  Eigen::VectorXd apply_inverse(const Eigen::VectorXd& r) const;

  static constexpr int max_changed_rows = 16;  // beyond: factorize afresh
  static constexpr double drift = 1e-2;         // relative row change left to refinement
  std::vector<Rows> factorized_;  // the pattern of A0_ (empty: none)
  Eigen::VectorXd E0_, mubar0_;   // the E = D1 - D(beta) and mubar of A0_
  Eigen::MatrixXd A0_, A0_inverse_;  // the factorized matrix and its inverse (by LU)
  Eigen::MatrixXd D_, Z_;            // low-rank update A = A0 + S D, Z = A0^-1 S
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance_;  // I + D Z
  int factorizations_ = 0;
};

}  // namespace rccm
