#include "rccm/contact/delassus.hpp"

#include "rccm/contact/solver_tuning.hpp"

#include "rccm/base/errors.hpp"

namespace rccm {

void DelassusOperator::gauss_seidel(int dim, const std::function<void(int)>& update, Eigen::VectorXd& y,
                                    Eigen::VectorXd& u) const {
  for (Eigen::Index first = 0; first < size(); first += dim) {
    const LocalVector old = y.segment(first, dim);
    update(static_cast<int>(first / dim));
    const LocalVector dy = y.segment(first, dim) - old;
    if (!dy.isZero(0.0)) add_response(first, dy, u);  // a pair left as it was (separated, at 0) moves nothing
  }
}

void DenseDelassus::multiply(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> u) const {
  u.noalias() = W_ * y;
}

void DenseDelassus::add_response(Eigen::Index first, const LocalVector& dy, Eigen::VectorXd& u) const {
  // The sweeps' inner loop (half a 3D run's time): the pair's 2-3 columns in one pass over u.
  const Eigen::Index m = W_.rows();
  const double* w = W_.data() + first * m;
  double* x = u.data();
  if (dy.size() == 2) {
    const double a = dy[0], b = dy[1];
    for (Eigen::Index i = 0; i < m; ++i) x[i] += w[i] * a + w[m + i] * b;
  } else {
    RCCM_VERIFY(dy.size() == 3, "add_response(): a pair has 2 or 3 components");
    const double a = dy[0], b = dy[1], c = dy[2];
    for (Eigen::Index i = 0; i < m; ++i) x[i] += w[i] * a + w[m + i] * b + w[2 * m + i] * c;
  }
}

CompressedDelassus::CompressedDelassus(HodlrMatrix W)
    : W_(std::move(W)),
      preconditioner_(W_.truncated(tuning::hodlr_preconditioner_accuracy)),
      diagonal_scale_(W_.diagonal_scale()) {
  W_.prepare_sweeps();
}

void CompressedDelassus::multiply(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> u) const {
  u = W_.multiply(y);
}

void CompressedDelassus::add_response(Eigen::Index first, const LocalVector& dy, Eigen::VectorXd& u) const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(size());
  y.segment(first, dy.size()) = dy;
  u += W_.multiply(y);
}

void CompressedDelassus::gauss_seidel(int dim, const std::function<void(int)>& update, Eigen::VectorXd& y,
                                      Eigen::VectorXd& u) const {
  RCCM_VERIFY(W_.granule() == dim, "gauss_seidel(): W0 was compressed for pairs of another size");
  W_.gauss_seidel([&](Eigen::Index first) { update(static_cast<int>(first / dim)); }, y, u);
}

SparseDelassus::SparseDelassus(Eigen::SparseMatrix<double> W) : W_(std::move(W)) {
  W_.makeCompressed();
  diagonal_scale_ = W_.rows() > 0 ? W_.diagonal().cwiseAbs().maxCoeff() : 0.0;
}

void SparseDelassus::multiply(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> u) const {
  u = W_ * y;
}

void SparseDelassus::add_response(Eigen::Index first, const LocalVector& dy, Eigen::VectorXd& u) const {
  for (Eigen::Index k = 0; k < dy.size(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(W_, first + k); it; ++it) u[it.row()] += it.value() * dy[k];
}

LocalMatrix SparseDelassus::block(Eigen::Index first, int n) const {
  LocalMatrix B = LocalMatrix::Zero(n, n);
  for (int j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(W_, first + j); it; ++it)
      if (it.row() >= first && it.row() < first + n) B(it.row() - first, j) = it.value();
  return B;
}

}  // namespace rccm
