#include "rccm/active_set.hpp"

#include <cmath>

namespace rccm {

Eigen::VectorXd ActiveSetSystem::residual(const ContactProblem& pb, const std::vector<Rows>& pattern,
                                          const Eigen::VectorXd& y) const {
  const Eigen::VectorXd u = *pb.W0 * y + pb.q0;
  const Eigen::VectorXd Rbar = y - (pb.D1 - pb.Dbeta).cwiseProduct(u);
  Eigen::VectorXd r(y.size());
  for (int i = 0; i < pb.size(); ++i) {
    const int t = 2 * i, n = 2 * i + 1;
    switch (pattern[i]) {
      case Rows::Free:
        r[t] = -Rbar[t], r[n] = -Rbar[n];
        break;
      case Rows::Stick:
        r[t] = pb.ut_ref[i] - u[t], r[n] = -pb.g0[i] - u[n];
        break;
      default: {
        const double sign = pattern[i] == Rows::SlidePositive ? 1.0 : -1.0;
        r[t] = -(Rbar[t] - sign * pb.mubar[i] * Rbar[n]), r[n] = -pb.g0[i] - u[n];
      }
    }
  }
  return r;
}

Eigen::Matrix<double, 2, Eigen::Dynamic> ActiveSetSystem::rows(const ContactProblem& pb, Rows kind, int i) const {
  const Eigen::MatrixXd& W = *pb.W0;
  const int t = 2 * i, n = 2 * i + 1;
  // Row of Rbar_c as a function of y: e_c - E_c W0_c.
  const auto rbar_row = [&](int c) -> Eigen::RowVectorXd {
    Eigen::RowVectorXd row = -(pb.D1[c] - pb.Dbeta[c]) * W.row(c);
    row[c] += 1.0;
    return row;
  };
  Eigen::Matrix<double, 2, Eigen::Dynamic> A(2, W.cols());
  switch (kind) {
    case Rows::Free:
      A.row(0) = rbar_row(t), A.row(1) = rbar_row(n);
      break;
    case Rows::Stick:
      A.row(0) = W.row(t), A.row(1) = W.row(n);
      break;
    default: {
      const double sign = kind == Rows::SlidePositive ? 1.0 : -1.0;
      A.row(0) = rbar_row(t) - sign * pb.mubar[i] * rbar_row(n), A.row(1) = W.row(n);
    }
  }
  return A;
}

bool ActiveSetSystem::rows_moved(const ContactProblem& pb, Rows kind, int i) const {
  if (kind == Rows::Stick) return false;  // u rows: no beta in them
  const auto moved = [&](int c) { return std::abs(pb.D1[c] - pb.Dbeta[c] - E0_[c]) > drift * pb.D1[c]; };
  const bool spring = moved(2 * i) || moved(2 * i + 1);
  return kind == Rows::Free ? spring : spring || std::abs(pb.mubar[i] - mubar0_[i]) > drift;
}

bool ActiveSetSystem::prepare_update(const ContactProblem& pb, const std::vector<Rows>& pattern) {
  std::vector<int> changed;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const int node = static_cast<int>(i);
    if (pattern[i] != factorized_[i] || rows_moved(pb, pattern[i], node)) changed.push_back(node);
  }
  const int c = 2 * static_cast<int>(changed.size()), m = static_cast<int>(A0_.rows());
  if (c > max_changed_rows) return false;
  if (c == 0) {  // the factorized matrix itself (Eigen's solves are undefined on 0 columns)
    D_.resize(0, m);
    return true;
  }
  // A = A0 + S D: rows 2i, 2i+1 of the changed nodes replaced (Sherman-Morrison-Woodbury);
  // Z = A0^-1 S is the changed nodes' columns of the inverse.
  D_.resize(c, m);
  Z_.resize(m, c);
  for (int k = 0; k < c / 2; ++k) {
    const int i = changed[k];
    D_.middleRows<2>(2 * k) = rows(pb, pattern[i], i) - A0_.middleRows<2>(2 * i);
    Z_.middleCols<2>(2 * k) = A0_inverse_.middleCols<2>(2 * i);
  }
  capacitance_.compute(Eigen::MatrixXd::Identity(c, c) + D_.lazyProduct(Z_));
  return true;
}

Eigen::VectorXd ActiveSetSystem::apply_inverse(const Eigen::VectorXd& r) const {
  Eigen::VectorXd x = A0_inverse_ * r;
  if (D_.rows() > 0) x -= Z_ * capacitance_.solve(D_ * x);
  return x;
}

Eigen::MatrixXd ActiveSetSystem::matrix(const ContactProblem& pb, const std::vector<Rows>& pattern) const {
  Eigen::MatrixXd A(pb.W0->rows(), pb.W0->cols());
  for (int i = 0; i < pb.size(); ++i) A.middleRows<2>(2 * i) = rows(pb, pattern[i], i);
  return A;
}

bool ActiveSetSystem::solve(const ContactProblem& pb, const std::vector<Rows>& pattern, Eigen::VectorXd& y) {
  Eigen::VectorXd r = residual(pb, pattern, y);
  const double r0 = r.norm();
  if (r0 == 0) return true;
  // Refinement with the factorization of an earlier beta and pattern (a few nodes changed:
  // low-rank update): each step must gain a factor 10, unless y has stopped moving.
  D_.resize(0, 0);
  if (factorized_.size() == pattern.size() && prepare_update(pb, pattern)) {
    double previous = r0;
    for (int k = 0; k < 6; ++k) {
      const Eigen::VectorXd dy = apply_inverse(r);
      const Eigen::VectorXd r_next = residual(pb, pattern, y + dy);
      const double norm = r_next.norm(), step = dy.norm(), size = y.norm();
      const bool still = step <= 1e-12 * size;
      if (!std::isfinite(norm) || (norm > 0.1 * previous && !still)) break;  // stale: factorize afresh
      y += dy, r = r_next, previous = norm;
      if (still || norm <= 1e-13 * r0) return true;
    }
  }
  D_.resize(0, 0);
  A0_ = matrix(pb, pattern);
  A0_inverse_ = Eigen::PartialPivLU<Eigen::MatrixXd>(A0_).inverse();
  ++factorizations_;
  if (!A0_inverse_.allFinite()) {
    factorized_.clear();
    return false;
  }
  factorized_ = pattern;
  E0_ = pb.D1 - pb.Dbeta;
  mubar0_ = pb.mubar;
  y += A0_inverse_ * r;
  return true;
}

}  // namespace rccm
