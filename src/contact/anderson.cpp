#include "rccm/contact/anderson.hpp"

#include <Eigen/QR>

namespace rccm {

double AndersonMixing::mix(const Eigen::VectorXd& y_in, Eigen::VectorXd& y, Eigen::VectorXd& u) {
  if (depth_ <= 0) return 0;
  const Eigen::Index m = y.size();
  f_ = y - y_in;  // the sweep's residual
  if (has_previous_) {
    if (dF_.rows() != m || dF_.cols() != depth_) dF_.resize(m, depth_), dG_.resize(m, depth_), dU_.resize(m, depth_);
    dF_.col(next_) = f_ - f_previous_;
    dG_.col(next_) = y - G_previous_;
    dU_.col(next_) = u - u_previous_;
    next_ = (next_ + 1) % depth_;
    count_ = std::min(count_ + 1, depth_);
  }
  f_previous_ = f_;
  G_previous_ = y;
  u_previous_ = u;
  has_previous_ = true;
  if (count_ == 0) return 0;
  qr_.compute(dF_.leftCols(count_));
  // No difference left at all (a sweep that repeats the same step: stagnation at round-off)
  // leaves nothing to combine, and the solve of a rank-0 factorization is not finite: the
  // sweep's iterate stands.
  if (qr_.rank() == 0) return 0;
  gamma_ = qr_.solve(f_);
  y.noalias() -= dG_.leftCols(count_) * gamma_;
  u.noalias() -= dU_.leftCols(count_) * gamma_;
  return gamma_.lpNorm<1>();
}

}  // namespace rccm
