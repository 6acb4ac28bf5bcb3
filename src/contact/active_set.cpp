#include "rccm/contact/active_set.hpp"

#include "rccm/contact/solver_tuning.hpp"
#include "rccm/la/gmres.hpp"

#include <cmath>

namespace rccm {

template <int dim>
Eigen::VectorXd ActiveSetSystem<dim>::constraint_values(const ContactProblem& pb, const Pattern& pattern,
                                                        const Eigen::VectorXd& y, const Eigen::VectorXd& u) const {
  const auto Rbar = [&](Eigen::Index c) { return y[c] - (pb.Dref[c] - pb.Dbeta[c]) * u[c]; };
  Eigen::VectorXd v(y.size());
  for (int i = 0; i < pb.size(); ++i) {
    const Eigen::Index first = Eigen::Index(dim) * i, n = first + dim - 1;
    switch (pattern[i].status) {
      case Status::Separated:
        for (int k = 0; k < dim; ++k) v[first + k] = Rbar(first + k);
        break;
      case Status::Stick:
        for (int k = 0; k < dim; ++k) v[first + k] = pattern[i].holds(k) ? Rbar(first + k) : u[first + k];
        break;
      case Status::Slide:
        for (int k = 0; k < dim - 1; ++k) v[first + k] = Rbar(first + k) - pattern[i].direction[k] * pb.mubar[i] * Rbar(n);
        v[n] = pattern[i].holds(dim - 1) ? Rbar(n) : u[n];
    }
  }
  return v;
}

template <int dim>
Eigen::VectorXd ActiveSetSystem<dim>::residual(const ContactProblem& pb, const Pattern& pattern,
                                               const Eigen::VectorXd& y, const Eigen::VectorXd& u) const {
  Eigen::VectorXd r = constraint_values(pb, pattern, y, u);
  r = -r;
  for (int i = 0; i < pb.size(); ++i) {
    if (pattern[i].status == Status::Separated) continue;
    const Eigen::Index first = Eigen::Index(dim) * i, n = first + dim - 1;
    if (pattern[i].status == Status::Stick)
      for (int k = 0; k < dim - 1; ++k)
        if (!pattern[i].holds(k)) r[first + k] += pb.u_ref[first + k];  // no slip
    if (!pattern[i].holds(dim - 1)) r[n] -= pb.g0[i];                   // closed gap
  }
  return r;
}

template <int dim>
void ActiveSetSystem<dim>::mixing(const ContactProblem& pb, const PairRows& kind, int i, Local& Cw, Local& Cy) const {
  const Eigen::Index first = Eigen::Index(dim) * i, n = dim - 1;
  const auto E = [&](int k) { return pb.Dref[first + k] - pb.Dbeta[first + k]; };
  Cw.setZero(), Cy.setZero();
  switch (kind.status) {
    case Status::Separated:  // Rbar = y - E u
      for (int k = 0; k < dim; ++k) Cw(k, k) = -E(k), Cy(k, k) = 1.0;
      break;
    case Status::Stick:  // u (Rbar where prescribed)
      for (int k = 0; k < dim; ++k)
        if (kind.holds(k))
          Cw(k, k) = -E(k), Cy(k, k) = 1.0;
        else
          Cw(k, k) = 1.0;
      break;
    case Status::Slide:  // Rbar_t - s Rbar_n, and u_n
      for (int k = 0; k < dim - 1; ++k) {
        const double s = kind.direction[k] * pb.mubar[i];
        Cw(k, k) = -E(k), Cw(k, n) = s * E(n);
        Cy(k, k) = 1.0, Cy(k, n) = -s;
      }
      if (kind.holds(n))
        Cw(n, n) = -E(n), Cy(n, n) = 1.0;
      else
        Cw(n, n) = 1.0;
  }
}

template <int dim>
template <class Rows>
void ActiveSetSystem<dim>::rows(const ContactProblem& pb, const PairRows& kind, int i, Rows&& out) const {
  const Eigen::MatrixXd& W = *pb.W0->dense();
  const Eigen::Index first = Eigen::Index(dim) * i;
  Local Cw, Cy;
  mixing(pb, kind, i, Cw, Cy);
  // Row c of W0 read as its column (W0 is symmetric: contiguous in memory).
  for (int k = 0; k < dim; ++k) {
    out.row(k).setZero();
    for (int j = 0; j < dim; ++j)
      if (Cw(k, j) != 0) out.row(k) += Cw(k, j) * W.col(first + j).transpose();
  }
  out.template middleCols<dim>(first) += Cy;
}

template <int dim>
void ActiveSetSystem<dim>::mixing(const ContactProblem& pb, const Pattern& pattern, Eigen::MatrixXd& Cw,
                                  Eigen::MatrixXd& Cy) const {
  const Eigen::Index m = pb.W0->size();
  Cw.resize(dim, m), Cy.resize(dim, m);
  for (int i = 0; i < pb.size(); ++i) {
    Local w, y;
    mixing(pb, pattern[i], i, w, y);
    Cw.template middleCols<dim>(Eigen::Index(dim) * i) = w, Cy.template middleCols<dim>(Eigen::Index(dim) * i) = y;
  }
}

template <int dim>
void ActiveSetSystem<dim>::record(const ContactProblem& pb, const Pattern& pattern, int i) {
  const Eigen::Index first = Eigen::Index(dim) * i;
  factorized_[i] = pattern[i];
  E0_.template segment<dim>(first) = pb.Dref.template segment<dim>(first) - pb.Dbeta.template segment<dim>(first);
  mubar0_[i] = pb.mubar[i];
}

template <int dim>
bool ActiveSetSystem<dim>::rows_moved(const ContactProblem& pb, const PairRows& kind, int i) const {
  if (kind.status == Status::Stick) return false;  // u rows (Rbar_k = y_k where held): no beta in them
  const Eigen::Index first = Eigen::Index(dim) * i;
  const double drift = hodlr_ ? tuning::row_drift_compressed : tuning::row_drift;
  bool spring = false;
  for (int k = 0; k < dim; ++k) {
    const Eigen::Index c = first + k;
    spring = spring || std::abs(pb.Dref[c] - pb.Dbeta[c] - E0_[c]) > drift * pb.Dref[c];
  }
  return kind.status == Status::Separated ? spring : spring || std::abs(pb.mubar[i] - mubar0_[i]) > drift;
}

template <int dim>
bool ActiveSetSystem<dim>::update(const ContactProblem& pb, const Pattern& pattern) {
  std::vector<int> changed;
  for (int i = 0; i < pb.size(); ++i)
    if (pattern[i] != factorized_[i] || rows_moved(pb, pattern[i], i)) changed.push_back(i);
  const Eigen::Index c = dim * static_cast<Eigen::Index>(changed.size()), m = pb.W0->size();
  if (hodlr_ && c > 0) {  // compressed: the changed rows mixed again, the leaves and bisections that hold them refactorized (no pending D_)
    std::vector<Eigen::Index> granules, rows;
    for (int i : changed) {
      granules.push_back(Eigen::Index(dim) * i);
      for (int d = 0; d < dim; ++d) rows.push_back(Eigen::Index(dim) * i + d);
    }
    Eigen::MatrixXd Cw, Cy;
    mixing(pb, pattern, Cw, Cy);
    mixed_->remix_rows(*pb.W0->compressed_preconditioner(), Cw, Cy, granules);
    hodlr_->refactorize(*mixed_, rows);
    for (int i : changed) record(pb, pattern, i);
    return true;
  }
  D_.resize(c, m);
  if (c == 0) return true;
  // A new factorization costs less than the update: over half the rows changed, or a
  // correction to fold with no inverse at hand (forming the inverse alone costs two
  // factorizations: 38 against 18 us at 66 rows; a cold solve's later exact steps).
  if (2 * c > m || (c > m / tuning::fold_fraction && !inverse_ready_)) return false;
  // A^-1 = A0^-1 - Z (I + D Z)^-1 D A0^-1 with Z = A0^-1 S, the changed rows' columns of A0^-1
  // (gathered from the inverse once there is one, c solves with the LU before).
  if (++reuses_ >= 2) inverse();
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(inverse_ready_ ? 0 : m, c);
  Z_.resize(m, c);
  for (std::size_t k = 0; k < changed.size(); ++k) {
    const int i = changed[k];
    const Eigen::Index row = dim * static_cast<Eigen::Index>(k), first = Eigen::Index(dim) * i;
    rows(pb, pattern[i], i, D_.template middleRows<dim>(row));
    D_.template middleRows<dim>(row) -= A0_.template middleRows<dim>(first);
    if (inverse_ready_)
      Z_.template middleCols<dim>(row) = A0_inverse_.template middleCols<dim>(first);
    else
      for (int d = 0; d < dim; ++d) S(first + d, row + d) = 1.0;
  }
  if (!inverse_ready_) Z_ = solve_A0(S);
  capacitance_.compute(Eigen::MatrixXd::Identity(c, c) + D_ * Z_);
  // Pending while small (c^2 m per solve, c m per product); beyond m/8 rows folded into A0.
  if (c <= m / tuning::fold_fraction) return true;
  const Eigen::MatrixXd correction = capacitance_.solve(D_ * inverse());
  if (!correction.allFinite()) return false;
  A0_inverse_.noalias() -= Z_ * correction;
  for (std::size_t k = 0; k < changed.size(); ++k) {
    const int i = changed[k];
    A0_.template middleRows<dim>(Eigen::Index(dim) * i) += D_.template middleRows<dim>(dim * static_cast<Eigen::Index>(k));
    record(pb, pattern, i);
  }
  D_.resize(0, m);
  return true;
}

template <int dim>
Eigen::VectorXd ActiveSetSystem<dim>::apply_inverse(const Eigen::VectorXd& r) {
  Eigen::VectorXd x = inverse_ready_ ? Eigen::VectorXd(A0_inverse_ * r) : Eigen::VectorXd(solve_A0(r));
  if (D_.rows() > 0) x -= Z_ * capacitance_.solve(D_ * x);
  return x;
}

template <int dim>
Eigen::MatrixXd ActiveSetSystem<dim>::solve_A0(const Eigen::MatrixXd& B) const {
  return hodlr_ ? hodlr_->solve(B) : Eigen::MatrixXd(lu_.solve(B));
}

template <int dim>
const Eigen::MatrixXd& ActiveSetSystem<dim>::inverse() {
  if (!inverse_ready_) A0_inverse_ = lu_.inverse();
  inverse_ready_ = true;
  return A0_inverse_;
}

template <int dim>
void ActiveSetSystem<dim>::factorize(const ContactProblem& pb, const Pattern& pattern) {
  const Eigen::Index m = pb.W0->size();
  hodlr_.reset();
  mixed_.reset();
  if (const HodlrMatrix* W0 = pb.W0->compressed_preconditioner()) {
    Eigen::MatrixXd Cw, Cy;
    mixing(pb, pattern, Cw, Cy);
    mixed_.emplace(W0->rows_mixed(Cw, Cy));
    hodlr_.emplace(*mixed_);
    A0_.resize(0, 0);
  } else {
    A0_.resize(m, m);
    for (int i = 0; i < pb.size(); ++i) rows(pb, pattern[i], i, A0_.template middleRows<dim>(Eigen::Index(dim) * i));
    lu_.compute(A0_);
  }
  inverse_ready_ = false;
  reuses_ = 0;
  factorized_ = pattern;
  E0_ = pb.Dref - pb.Dbeta;
  mubar0_ = pb.mubar;
  D_.resize(0, m);
}

template <int dim>
bool ActiveSetSystem<dim>::refine(const ContactProblem& pb, const Pattern& pattern, Eigen::VectorXd& r,
                                  Eigen::VectorXd& y, Eigen::VectorXd& u) {
  const DelassusOperator& W = *pb.W0;
  const double r0 = r.norm();
  // A correction is taken when it gains a factor 10 on the residual, or leaves y unmoved.
  enum class Outcome { Converged, Progress, Stalled };
  double previous = r0;
  const auto take = [&](const Eigen::VectorXd& dy, const Eigen::VectorXd& du) {
    const Eigen::VectorXd r_next = residual(pb, pattern, y + dy, u + du);
    const double norm = r_next.norm();
    const bool still = dy.norm() <= tuning::unmoved * y.norm();
    if (!std::isfinite(norm) || (norm > tuning::refinement_gain * previous && !still)) return Outcome::Stalled;
    y += dy, u += du, r = r_next, previous = norm;
    return still || norm <= tuning::converged_residual * r0 ? Outcome::Converged : Outcome::Progress;
  };
  // Refinement with the corrected inverse: two products of W0's size per step.
  Outcome outcome = Outcome::Progress;
  for (int k = 0; k < tuning::refinement_steps && outcome == Outcome::Progress; ++k) {
    const Eigen::VectorXd dy = apply_inverse(r);
    Eigen::VectorXd du(dy.size());
    W.multiply(dy, du);
    outcome = take(dy, du);
  }
  // Stalled or slow (the inverse's round-off, or a drift it does not absorb): GMRES with the
  // same preconditioner, before a new factorization. The products W0 M v it forms are kept, so
  // that u follows y without one more product with W0.
  if (outcome != Outcome::Converged) {
    const int max_iterations = tuning::gmres_iterations;
    Eigen::MatrixXd Wz(W.size(), max_iterations);
    int products = 0;
    const LinearMap A = [&](const Eigen::VectorXd& z) -> Eigen::VectorXd {
      W.multiply(z, Wz.col(products));
      return constraint_values(pb, pattern, z, Wz.col(products++));
    };
    const LinearMap M = [&](const Eigen::VectorXd& v) { return apply_inverse(v); };
    outcome = Outcome::Progress;
    for (int pass = 0; pass < tuning::gmres_passes && outcome == Outcome::Progress; ++pass) {
      products = 0;
      const GmresResult g = gmres(A, M, r, tuning::gmres_tolerance, max_iterations);
      outcome = g.iterations == 0 ? Outcome::Stalled : take(g.x, Wz.leftCols(g.iterations) * g.coefficients);
    }
  }
  return outcome == Outcome::Converged;
}

template <int dim>
void ActiveSetSystem<dim>::forget() {
  factorized_.clear();
  mixed_.reset();
  hodlr_.reset();
  A0_.resize(0, 0);
  A0_inverse_.resize(0, 0);
  inverse_ready_ = false;
}

template <int dim>
bool ActiveSetSystem<dim>::solve(const ContactProblem& pb, const Pattern& pattern, Eigen::VectorXd& y,
                                 Eigen::VectorXd& u) {
  Eigen::VectorXd r = residual(pb, pattern, y, u);
  if (r.norm() == 0) return true;
  if (factorized_.size() == pattern.size() && update(pb, pattern) && refine(pb, pattern, r, y, u)) return true;
  factorize(pb, pattern);
  const Eigen::VectorXd dy = solve_A0(r);
  if (!dy.allFinite()) {  // singular
    factorized_.clear();
    return false;
  }
  y += dy;
  pb.W0->multiply(y, u);
  u += pb.q0;
  if (hodlr_) {  // the compressed factorization solved the rows to its accuracy: refined by W0's products
    r = residual(pb, pattern, y, u);
    refine(pb, pattern, r, y, u);
  }
  return true;
}

template class ActiveSetSystem<2>;
template class ActiveSetSystem<3>;

}  // namespace rccm
