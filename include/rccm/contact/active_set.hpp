// The exact step of the bipotential solver (docs/MODEL.md s5): once the status of every
// pair repeats, the contact problem is linear,
//   separated  Rbar_i = 0,
//   stick      u_i = (u_ref,t,i, -g0_i),
//   slide      u_n,i = -g0_i  and  Rbar_t,i = mubar_i Rbar_n,i d_i  (d_i the slide direction),
// where a component of u_i is prescribed (a support on the contact node: W0's row is zero) its
// row reads Rbar_k = 0 instead (the law holds for any Rbar_k there; the support carries it),
// with u = W0 y + q0 and Rbar = y - E u in the unknown y. Its residual and its product
// with a vector cost one product with W0 each.
// The system keeps A0, the matrix of an earlier pattern and beta, and its explicit inverse.
// The rows of the pairs whose status changed or whose beta moved (E, mubar) since then are a
// low-rank (Sherman-Morrison-Woodbury) correction of that inverse, kept pending while their
// count is small (c^2 m per solve) and folded into the inverse beyond (2 c m^2 once, instead
// of the 2 m^3 of a new factorization and inverse); where the inverse is not formed yet (a
// factorization's first reuse: a cold solve's next exact step), a new factorization instead.
// GMRES preconditioned by that corrected inverse absorbs the small drift of the other rows
// and the inverse's own round-off. A new factorization only when GMRES stalls or most rows
// changed. Needs a dense W0.
// When W0 is kept compressed (solver.compressed_min_nodes pairs on; la/hodlr.hpp: the off-diagonal
// blocks of an interface line's flexibility have low rank r), A0 = C_y + C_w W0 is mixed
// from it row by row and factorized compressed, at about m r^2 log^2 m instead of m^3, without
// the dense A0: no explicit inverse, no pending corrections (the leaves and bisections that
// hold changed rows are refactorized instead, the others kept), and the compressed solve is a
// preconditioner that refinement and GMRES bring to the rows of W0's products (themselves
// compressed, to tuning::hodlr_accuracy).
// Written for the pairs' dimension (2 or 3) as a template, as the solver's inner loops.
#pragma once

#include "rccm/contact/contact_problem.hpp"
#include "rccm/contact/solver_tuning.hpp"
#include "rccm/la/hodlr.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

#include <optional>
#include <vector>

namespace rccm {

/// Which linear rows a pair contributes: its status and, sliding, the slide direction
/// (a tangential unit vector: (+1 or -1, 0) in 2D).
/// Two are the same rows when the status agrees and, sliding, the directions agree to
/// tuning::slide_direction_drift (in 2D they are +-1: equal or opposite).
struct PairRows {
  Status status = Status::Separated;
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();
  unsigned held = 0;  // bit k: component k prescribed (PairBlock::held): its u row reads Rbar_k = 0
  bool holds(int k) const { return (held >> k) & 1u; }
  bool operator==(const PairRows& o) const {
    return status == o.status && held == o.held &&
           (status != Status::Slide || (direction - o.direction).norm() <= tuning::slide_direction_drift);
  }
  bool operator!=(const PairRows& o) const { return !(*this == o); }
};
using Pattern = std::vector<PairRows>;

template <int dim>
class ActiveSetSystem {
 public:
  /// Improves y towards the solution of the pattern's linear problem, with u = W0 y + q0
  /// given and kept in step. Returns false when the pattern's matrix is singular (the caller
  /// goes on sweeping).
  bool solve(const ContactProblem& pb, const Pattern& pattern, Eigen::VectorXd& y, Eigen::VectorXd& u);

  const Pattern& pattern() const { return factorized_; }  // of the factorized matrix
  /// Drops the factorization: the next solve factorizes afresh (W0 changed).
  void forget();

 private:
  /// The left-hand sides of the pattern's rows at (y, u), with Rbar = y - E u: Rbar (separated),
  /// u (stick), Rbar_t - mubar Rbar_n d and u_n (slide). At (v, W0 v) it is the matrix times v.
  Eigen::VectorXd constraint_values(const ContactProblem& pb, const Pattern& pattern, const Eigen::VectorXd& y,
                                    const Eigen::VectorXd& u) const;
  /// Right-hand sides minus constraint_values: zero at the solution.
  Eigen::VectorXd residual(const ContactProblem& pb, const Pattern& pattern, const Eigen::VectorXd& y,
                           const Eigen::VectorXd& u) const;
  using Local = Eigen::Matrix<double, dim, dim>;
  /// Pair i's rows of the pattern's matrix are C_w (W0's rows of the pair) + C_y (the pair's
  /// columns of the identity).
  void mixing(const ContactProblem& pb, const PairRows& kind, int i, Local& Cw, Local& Cy) const;
  /// Pair i's rows of the pattern's matrix, written into `out`.
  template <class Rows>
  void rows(const ContactProblem& pb, const PairRows& kind, int i, Rows&& out) const;
  /// All pairs' C_w and C_y side by side (dim x m each), for W0's compression.
  void mixing(const ContactProblem& pb, const Pattern& pattern, Eigen::MatrixXd& Cw, Eigen::MatrixXd& Cy) const;
  /// Pair i's rows are now factorized as the pattern and the problem's beta give them.
  void record(const ContactProblem& pb, const Pattern& pattern, int i);
  /// Whether pair i's rows moved since they were factorized by more than refinement absorbs cheaply.
  bool rows_moved(const ContactProblem& pb, const PairRows& kind, int i) const;
  /// Sets up the pending correction for the changed pairs, or folds it into A0 and its
  /// inverse when it is large; false when a new factorization is due.
  bool update(const ContactProblem& pb, const Pattern& pattern);
  /// The inverse of A0 with the pending correction, times r.
  Eigen::VectorXd apply_inverse(const Eigen::VectorXd& r);
  /// A0^-1 B: by the LU, or by the compressed factorization.
  Eigen::MatrixXd solve_A0(const Eigen::MatrixXd& B) const;
  /// Refinement of y (and u) with apply_inverse, then GMRES where refinement stalls: true once
  /// the pattern's residual r is converged.
  bool refine(const ContactProblem& pb, const Pattern& pattern, Eigen::VectorXd& r, Eigen::VectorXd& y,
              Eigen::VectorXd& u);
  /// A0 and its LU afresh.
  void factorize(const ContactProblem& pb, const Pattern& pattern);
  /// The inverse of A0, from its LU. Computed once the factorization is reused a second time
  /// (then every use is one product); a solve that needs it once or twice, a cold one, uses
  /// the LU and pays no inverse.
  const Eigen::MatrixXd& inverse();

  Pattern factorized_;                   // the pattern of A0_ (empty: none)
  Eigen::VectorXd E0_, mubar0_;          // the E = Dref - D(beta) and mubar of A0_'s rows
  Eigen::MatrixXd A0_, A0_inverse_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;  // of A0_ as factorized (before any fold)
  std::optional<HodlrMatrix> mixed_;        // A0 compressed (W0 compressed), mixed from W0's compression
  std::optional<HodlrSolver> hodlr_;        // its factorization, instead of A0_ and lu_
  bool inverse_ready_ = false;
  int reuses_ = 0;  // updates since the factorization
  // Pending correction A = A0 + S D (S: unit columns of the changed rows), Z = A0^-1 S.
  Eigen::MatrixXd D_, Z_;
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance_;  // I + D Z
};

extern template class ActiveSetSystem<2>;
extern template class ActiveSetSystem<3>;

}  // namespace rccm
