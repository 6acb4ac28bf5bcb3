#include "rccm/active_set.hpp"

#include <Eigen/LU>

#include <cmath>

namespace rccm {

Eigen::VectorXd ActiveSetSystem::residual(const ContactProblem& pb, const std::vector<Rows>& pattern,
                                          const Eigen::VectorXd& y, const Eigen::VectorXd& u) const {
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

bool ActiveSetSystem::update(const ContactProblem& pb, const std::vector<Rows>& pattern) {
  std::vector<int> changed;
  for (int i = 0; i < pb.size(); ++i)
    if (pattern[i] != factorized_[i] || rows_moved(pb, pattern[i], i)) changed.push_back(i);
  const Eigen::Index c = 2 * static_cast<Eigen::Index>(changed.size()), m = A0_.rows();
  if (c == 0) return true;
  if (2 * c > m) return false;  // a new factorization costs less
  // A = A0 + S D with S the unit columns of the changed rows:
  //   A^-1 = A0^-1 - Z (I + D Z)^-1 D A0^-1,  Z = A0^-1 S (columns of the inverse).
  Eigen::MatrixXd D(c, m), Z(m, c);
  for (Eigen::Index k = 0; k < c / 2; ++k) {
    const int i = changed[k];
    D.middleRows<2>(2 * k) = rows(pb, pattern[i], i) - A0_.middleRows<2>(2 * i);
    Z.middleCols<2>(2 * k) = A0_inverse_.middleCols<2>(2 * i);
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> capacitance(Eigen::MatrixXd::Identity(c, c) + D * Z);
  const Eigen::MatrixXd correction = capacitance.solve(D * A0_inverse_);
  if (!correction.allFinite()) return false;
  A0_inverse_.noalias() -= Z * correction;
  for (Eigen::Index k = 0; k < c / 2; ++k) {
    const int i = changed[k];
    A0_.middleRows<2>(2 * i) += D.middleRows<2>(2 * k);
    factorized_[i] = pattern[i];
    E0_.segment<2>(2 * i) = pb.D1.segment<2>(2 * i) - pb.Dbeta.segment<2>(2 * i);
    mubar0_[i] = pb.mubar[i];
  }
  return true;
}

bool ActiveSetSystem::factorize(const ContactProblem& pb, const std::vector<Rows>& pattern) {
  A0_.resize(pb.W0->rows(), pb.W0->cols());
  for (int i = 0; i < pb.size(); ++i) A0_.middleRows<2>(2 * i) = rows(pb, pattern[i], i);
  A0_inverse_ = Eigen::PartialPivLU<Eigen::MatrixXd>(A0_).inverse();
  ++factorizations_;
  if (!A0_inverse_.allFinite()) {
    factorized_.clear();
    return false;
  }
  factorized_ = pattern;
  E0_ = pb.D1 - pb.Dbeta;
  mubar0_ = pb.mubar;
  return true;
}

bool ActiveSetSystem::solve(const ContactProblem& pb, const std::vector<Rows>& pattern, Eigen::VectorXd& y,
                            Eigen::VectorXd& u) {
  const Eigen::MatrixXd& W = *pb.W0;
  Eigen::VectorXd r = residual(pb, pattern, y, u);
  const double r0 = r.norm();
  if (r0 == 0) return true;
  // Refinement with the updated inverse: each step must gain a factor 10, unless y has
  // stopped moving; otherwise the inverse has gone stale and is computed afresh.
  if (factorized_.size() == pattern.size() && update(pb, pattern)) {
    double previous = r0;
    for (int k = 0; k < 6; ++k) {
      const Eigen::VectorXd dy = A0_inverse_ * r;
      const Eigen::VectorXd u_next = u + W * dy;
      const Eigen::VectorXd r_next = residual(pb, pattern, y + dy, u_next);
      const double norm = r_next.norm(), step = dy.norm(), size = y.norm();
      const bool still = step <= 1e-12 * size;
      if (!std::isfinite(norm) || (norm > 0.1 * previous && !still)) break;
      y += dy, u = u_next, r = r_next, previous = norm;
      if (still || norm <= 1e-13 * r0) return true;
    }
  }
  if (!factorize(pb, pattern)) return false;
  y += A0_inverse_ * r;
  u.noalias() = W * y;
  u += pb.q0;
  return true;
}

}  // namespace rccm
