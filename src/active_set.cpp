#include "rccm/active_set.hpp"

#include "rccm/gmres.hpp"

#include <cmath>

namespace rccm {

namespace {
double slide_sign(Rows kind) { return kind == Rows::SlidePositive ? 1.0 : -1.0; }
}  // namespace

Eigen::VectorXd ActiveSetSystem::constraint_values(const ContactProblem& pb, const std::vector<Rows>& pattern,
                                                   const Eigen::VectorXd& y, const Eigen::VectorXd& u) const {
  const auto Rbar = [&](int c) { return y[c] - (pb.D1[c] - pb.Dbeta[c]) * u[c]; };
  Eigen::VectorXd v(y.size());
  for (int i = 0; i < pb.size(); ++i) {
    const int t = 2 * i, n = 2 * i + 1;
    switch (pattern[i]) {
      case Rows::Free:
        v[t] = Rbar(t), v[n] = Rbar(n);
        break;
      case Rows::Stick:
        v[t] = u[t], v[n] = u[n];
        break;
      default:
        v[t] = Rbar(t) - slide_sign(pattern[i]) * pb.mubar[i] * Rbar(n), v[n] = u[n];
    }
  }
  return v;
}

Eigen::VectorXd ActiveSetSystem::residual(const ContactProblem& pb, const std::vector<Rows>& pattern,
                                          const Eigen::VectorXd& y, const Eigen::VectorXd& u) const {
  Eigen::VectorXd r = constraint_values(pb, pattern, y, u);
  r = -r;
  for (int i = 0; i < pb.size(); ++i) {
    if (pattern[i] == Rows::Free) continue;
    if (pattern[i] == Rows::Stick) r[2 * i] += pb.ut_ref[i];  // no slip
    r[2 * i + 1] -= pb.g0[i];                                  // closed gap
  }
  return r;
}

void ActiveSetSystem::rows(const ContactProblem& pb, Rows kind, int i, RowPair out) const {
  const Eigen::MatrixXd& W = *pb.W0;
  const int t = 2 * i, n = 2 * i + 1;
  const double Et = pb.D1[t] - pb.Dbeta[t], En = pb.D1[n] - pb.Dbeta[n];
  // Row c of W0 read as its column (W0 is symmetric: contiguous in memory). The row of Rbar_c
  // as a function of y is e_c - E_c W0_c.
  switch (kind) {
    case Rows::Free:
      out.row(0) = -Et * W.col(t).transpose(), out(0, t) += 1.0;
      out.row(1) = -En * W.col(n).transpose(), out(1, n) += 1.0;
      break;
    case Rows::Stick:
      out.row(0) = W.col(t).transpose(), out.row(1) = W.col(n).transpose();
      break;
    default: {
      const double s = slide_sign(kind) * pb.mubar[i];  // Rbar_t - s Rbar_n
      out.row(0) = -Et * W.col(t).transpose() + s * En * W.col(n).transpose();
      out(0, t) += 1.0, out(0, n) -= s;
      out.row(1) = W.col(n).transpose();
    }
  }
}

bool ActiveSetSystem::rows_moved(const ContactProblem& pb, Rows kind, int i) const {
  if (kind == Rows::Stick) return false;  // u rows: no beta in them
  const auto moved = [&](int c) { return std::abs(pb.D1[c] - pb.Dbeta[c] - E0_[c]) > drift * pb.D1[c]; };
  const bool spring = moved(2 * i) || moved(2 * i + 1);
  return kind == Rows::Free ? spring : spring || std::abs(pb.mubar[i] - mubar0_[i]) > drift;
}

bool ActiveSetSystem::update(const ContactProblem& pb, const std::vector<Rows>& pattern) {
  std::vector<int> changed;
  for (int i = 0; i < pb.size(); ++i)
    if (pattern[i] != factorized_[i] || rows_moved(pb, pattern[i], i)) changed.push_back(i);
  const Eigen::Index c = 2 * static_cast<Eigen::Index>(changed.size()), m = A0_.rows();
  D_.resize(c, m);
  if (c == 0) return true;
  if (2 * c > m) return false;  // a new factorization costs less
  // A^-1 = A0^-1 - Z (I + D Z)^-1 D A0^-1 with Z = A0^-1 S, the changed rows' columns of A0^-1
  // (gathered from the inverse once there is one, c solves with the LU before).
  if (++reuses_ >= 2) inverse();
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(inverse_ready_ ? 0 : m, c);
  Z_.resize(m, c);
  for (Eigen::Index k = 0; k < c / 2; ++k) {
    const int i = changed[k];
    rows(pb, pattern[i], i, D_.middleRows<2>(2 * k));
    D_.middleRows<2>(2 * k) -= A0_.middleRows<2>(2 * i);
    if (inverse_ready_)
      Z_.middleCols<2>(2 * k) = A0_inverse_.middleCols<2>(2 * i);
    else
      S(2 * i, 2 * k) = S(2 * i + 1, 2 * k + 1) = 1.0;
  }
  if (!inverse_ready_) Z_ = lu_.solve(S);
  capacitance_.compute(Eigen::MatrixXd::Identity(c, c) + D_ * Z_);
  // Pending while small (c^2 m per solve, c m per product); beyond m/8 rows folded into A0.
  if (c <= m / 8) return true;
  const Eigen::MatrixXd correction = capacitance_.solve(D_ * inverse());
  if (!correction.allFinite()) return false;
  A0_inverse_.noalias() -= Z_ * correction;
  for (Eigen::Index k = 0; k < c / 2; ++k) {
    const int i = changed[k];
    A0_.middleRows<2>(2 * i) += D_.middleRows<2>(2 * k);
    factorized_[i] = pattern[i];
    E0_.segment<2>(2 * i) = pb.D1.segment<2>(2 * i) - pb.Dbeta.segment<2>(2 * i);
    mubar0_[i] = pb.mubar[i];
  }
  D_.resize(0, m);
  return true;
}

Eigen::VectorXd ActiveSetSystem::apply_inverse(const Eigen::VectorXd& r) {
  Eigen::VectorXd x = inverse_ready_ ? Eigen::VectorXd(A0_inverse_ * r) : Eigen::VectorXd(lu_.solve(r));
  if (D_.rows() > 0) x -= Z_ * capacitance_.solve(D_ * x);
  return x;
}

const Eigen::MatrixXd& ActiveSetSystem::inverse() {
  if (!inverse_ready_) A0_inverse_ = lu_.inverse();
  inverse_ready_ = true;
  return A0_inverse_;
}

void ActiveSetSystem::factorize(const ContactProblem& pb, const std::vector<Rows>& pattern) {
  A0_.resize(pb.W0->rows(), pb.W0->cols());
  for (int i = 0; i < pb.size(); ++i) rows(pb, pattern[i], i, A0_.middleRows<2>(2 * i));
  lu_.compute(A0_);
  inverse_ready_ = false;
  reuses_ = 0;
  ++factorizations_;
  factorized_ = pattern;
  E0_ = pb.D1 - pb.Dbeta;
  mubar0_ = pb.mubar;
  D_.resize(0, A0_.rows());
}

bool ActiveSetSystem::solve(const ContactProblem& pb, const std::vector<Rows>& pattern, Eigen::VectorXd& y,
                            Eigen::VectorXd& u) {
  const Eigen::MatrixXd& W = *pb.W0;
  Eigen::VectorXd r = residual(pb, pattern, y, u);
  const double r0 = r.norm();
  if (r0 == 0) return true;
  if (factorized_.size() == pattern.size() && update(pb, pattern)) {
    // A correction is taken when it gains a factor 10 on the residual, or leaves y unmoved.
    enum class Outcome { Converged, Progress, Stalled };
    double previous = r0;
    const auto take = [&](const Eigen::VectorXd& dy, const Eigen::VectorXd& du) {
      const Eigen::VectorXd r_next = residual(pb, pattern, y + dy, u + du);
      const double norm = r_next.norm();
      const bool still = dy.norm() <= 1e-12 * y.norm();
      if (!std::isfinite(norm) || (norm > 0.1 * previous && !still)) return Outcome::Stalled;
      y += dy, u += du, r = r_next, previous = norm;
      return still || norm <= 1e-13 * r0 ? Outcome::Converged : Outcome::Progress;
    };
    // Refinement with the corrected inverse: two products of W0's size per step.
    Outcome outcome = Outcome::Progress;
    for (int k = 0; k < 6 && outcome == Outcome::Progress; ++k) {
      const Eigen::VectorXd dy = apply_inverse(r);
      outcome = take(dy, W * dy);
    }
    // Stalled or slow (the inverse's round-off, or a drift it does not absorb): GMRES with the
    // same preconditioner, before a new factorization. The products W0 M v it forms are kept, so
    // that u follows y without one more product with W0.
    if (outcome != Outcome::Converged) {
      const int max_iterations = 30;
      Eigen::MatrixXd Wz(W.rows(), max_iterations);
      int products = 0;
      const LinearMap A = [&](const Eigen::VectorXd& z) -> Eigen::VectorXd {
        Wz.col(products).noalias() = W * z;
        return constraint_values(pb, pattern, z, Wz.col(products++));
      };
      const LinearMap M = [&](const Eigen::VectorXd& v) { return apply_inverse(v); };
      outcome = Outcome::Progress;
      for (int pass = 0; pass < 3 && outcome == Outcome::Progress; ++pass) {
        products = 0;
        const GmresResult g = gmres(A, M, r, 1e-6, max_iterations);
        outcome = g.iterations == 0 ? Outcome::Stalled : take(g.x, Wz.leftCols(g.iterations) * g.coefficients);
      }
    }
    if (outcome == Outcome::Converged) return true;
  }
  factorize(pb, pattern);
  const Eigen::VectorXd dy = lu_.solve(r);
  if (!dy.allFinite()) {  // singular
    factorized_.clear();
    return false;
  }
  y += dy;
  u.noalias() = W * y;
  u += pb.q0;
  return true;
}

}  // namespace rccm
