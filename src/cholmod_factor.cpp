#include "rccm/cholmod_factor.hpp"

#include <Eigen/CholmodSupport>

namespace rccm {

// Eigen's wrapper, opened up to read CHOLMOD's reciprocal condition estimate.
struct CholmodFactor::Impl : Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> {
  double rcond() { return cholmod_rcond(m_cholmodFactor, &cholmod()); }
};

CholmodFactor::CholmodFactor(const Eigen::SparseMatrix<double>& A) : impl_(std::make_unique<Impl>()) {
  impl_->compute(A);
  ok_ = impl_->info() == Eigen::Success;
  if (ok_) rcond_ = impl_->rcond();
}

CholmodFactor::~CholmodFactor() = default;

Eigen::MatrixXd CholmodFactor::solve(const Eigen::MatrixXd& b) const { return impl_->solve(b); }

}  // namespace rccm
