#include "rccm/contact/delassus.hpp"

#include "rccm/contact/solver_tuning.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/format.hpp"
#include "rccm/la/blas_threads.hpp"

namespace rccm {

namespace {

/// The largest magnitude on a stored (dense or sparse) matrix's diagonal; 0 for no rows.
template <class Matrix>
double largest_on_diagonal(const Matrix& W) {
  return W.rows() > 0 ? W.diagonal().cwiseAbs().maxCoeff() : 0.0;
}

/// "rows x rows" and the MB of `doubles`.
std::string shape_and_memory(Eigen::Index rows, double doubles) {
  return std::to_string(rows) + " x " + std::to_string(rows) + " (" + fmt("%.3g", doubles * sizeof(double) / 1e6) + " MB";
}

}  // namespace

void DelassusOperator::gauss_seidel(int dim, const std::function<void(int)>& update, Eigen::VectorXd& y,
                                    Eigen::VectorXd& u, const SweepBlocks& blocks) const {
  const auto respond = [&](Eigen::Index first, const LocalVector& dy) { add_response(first, dy, u); };
  const Eigen::Index m = y.size(), rows = block_rows(blocks, dim, m);
  for (Eigen::Index begin = 0; begin < m; begin += rows)
    for (int k = 0; k < std::max(blocks.sweeps, 1); ++k)
      pass_over_pairs<LocalVector>(dim, update, respond, y, begin, std::min(begin + rows, m));
}

DenseDelassus::DenseDelassus(Eigen::MatrixXd W)
    : W_(std::move(W)), diagonal_scale_(largest_on_diagonal(W_)) {}

std::string DenseDelassus::storage() const { return "dense, " + shape_and_memory(size(), double(W_.size())) + ")"; }

void DenseDelassus::multiply(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> u) const {
  u.noalias() = W_ * y;
}

void DenseDelassus::add_response(Eigen::Index first, const LocalVector& dy, Eigen::VectorXd& u) const {
  if (dy.size() == 2) return add_columns<2>(W_, first, dy, u, 0, size());
  RCCM_VERIFY(dy.size() == 3, "add_response(): a pair has 2 or 3 components");
  add_columns<3>(W_, first, dy, u, 0, size());
}

CompressedDelassus::CompressedDelassus(HodlrMatrix W) : W_(std::move(W)), diagonal_scale_(W_.diagonal_scale()) {}

const HodlrMatrix* CompressedDelassus::compressed_preconditioner() const {
  if (!preconditioner_) preconditioner_.emplace(W_.truncated(tuning::hodlr_preconditioner_accuracy));
  return &*preconditioner_;
}

std::string CompressedDelassus::storage() const {
  const double m = double(size()), stored = double(W_.stored());
  return "compressed (HODLR), " + shape_and_memory(size(), stored) + ", " + fmt("%.0f", 100.0 * stored / (m * m)) +
         " % of dense), largest rank " + std::to_string(W_.max_rank()) + ", its large blocks in " +
         std::to_string(blas_threads::most_products()) + " thread(s)";
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
                                      Eigen::VectorXd& u, const SweepBlocks& blocks) const {
  RCCM_VERIFY(W_.granule() == dim, "gauss_seidel(): W0 was compressed for pairs of another size");
  W_.gauss_seidel([&](Eigen::Index first) { update(static_cast<int>(first / dim)); }, y, u, blocks);
}

SparseDelassus::SparseDelassus(Eigen::SparseMatrix<double> W) : W_(std::move(W)) {
  W_.makeCompressed();
  diagonal_scale_ = largest_on_diagonal(W_);
}

std::string SparseDelassus::storage() const {
  // A nonzero: its value and its row index (an int), 1.5 doubles.
  return "sparse, " + shape_and_memory(size(), 1.5 * double(W_.nonZeros())) + ", " + std::to_string(W_.nonZeros()) + " nonzeros)";
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
