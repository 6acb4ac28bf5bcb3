// The exact step of the bipotential solver (MODEL.md s5): once the status of every node
// repeats, the contact problem is linear,
//   separated  Rbar_i = 0,
//   stick      u_i = (ut_ref_i, -g0_i),
//   slide      u_n,i = -g0_i  and  Rbar_t,i = sign_i mubar_i Rbar_n,i,
// with u = W0 y + q0 and Rbar = y - E u in the unknown y. Its residual and its product
// with a vector cost one product with W0 each.
// The system keeps A0, the matrix of an earlier pattern and beta, and its explicit inverse.
// The rows of the nodes whose status changed or whose beta moved (E, mubar) since then are a
// low-rank (Sherman-Morrison-Woodbury) correction of that inverse, kept pending while their
// count is small (c^2 m per solve) and folded into the inverse beyond (2 c m^2 once, instead
// of the 2 m^3 of a new factorization and inverse). GMRES preconditioned by that corrected
// inverse absorbs the small drift of the other rows and the inverse's own round-off. A new
// factorization only when GMRES stalls or most rows changed.
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
  /// Improves y towards the solution of the pattern's linear problem, with u = W0 y + q0
  /// given and kept in step. Returns false when the pattern's matrix is singular (the caller
  /// goes on sweeping).
  bool solve(const ContactProblem& pb, const std::vector<Rows>& pattern, Eigen::VectorXd& y, Eigen::VectorXd& u);

  int factorizations() const { return factorizations_; }
  const std::vector<Rows>& pattern() const { return factorized_; }  // of the factorized matrix

 private:
  /// The left-hand sides of the pattern's rows at (y, u), with Rbar = y - E u: Rbar (separated),
  /// u (stick), Rbar_t - sign mubar Rbar_n and u_n (slide). At (v, W0 v) it is the matrix times v.
  Eigen::VectorXd constraint_values(const ContactProblem& pb, const std::vector<Rows>& pattern,
                                    const Eigen::VectorXd& y, const Eigen::VectorXd& u) const;
  /// Right-hand sides minus constraint_values: zero at the solution.
  Eigen::VectorXd residual(const ContactProblem& pb, const std::vector<Rows>& pattern, const Eigen::VectorXd& y,
                           const Eigen::VectorXd& u) const;
  /// Node i's two rows of the pattern's matrix, written into `out`.
  using RowPair = Eigen::Ref<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
  void rows(const ContactProblem& pb, Rows kind, int i, RowPair out) const;
  /// Whether node i's rows moved since they were factorized by more than refinement absorbs cheaply.
  bool rows_moved(const ContactProblem& pb, Rows kind, int i) const;
  /// Sets up the pending correction for the changed nodes, or folds it into A0 and its
  /// inverse when it is large; false when a new factorization is due.
  bool update(const ContactProblem& pb, const std::vector<Rows>& pattern);
  /// The inverse of A0 with the pending correction, times r.
  Eigen::VectorXd apply_inverse(const Eigen::VectorXd& r);
  /// A0 and its LU afresh.
  void factorize(const ContactProblem& pb, const std::vector<Rows>& pattern);
  /// The inverse of A0, from its LU. Computed once the factorization is reused a second time
  /// (then every use is one product); a solve that needs it once or twice, a cold one, uses
  /// the LU and pays no inverse.
  const Eigen::MatrixXd& inverse();

  static constexpr double drift = 1e-3;  // relative row change left to refinement (GMRES if it stalls)
  std::vector<Rows> factorized_;         // the pattern of A0_ (empty: none)
  Eigen::VectorXd E0_, mubar0_;          // the E = D1 - D(beta) and mubar of A0_'s rows
  Eigen::MatrixXd A0_, A0_inverse_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;  // of A0_ as factorized (before any fold)
  bool inverse_ready_ = false;
  int reuses_ = 0;  // updates since the factorization
  // Pending correction A = A0 + S D (S: unit columns of the changed rows), Z = A0^-1 S.
  Eigen::MatrixXd D_, Z_;
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance_;  // I + D Z
  int factorizations_ = 0;
};

}  // namespace rccm
