// One Cholesky factorization of a sparse SPD matrix by SuiteSparse CHOLMOD.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace rccm {

class CholmodFactor {
 public:
  /// Factorizes A (symmetric; both triangles stored). `ok()` is false when A is not
  /// numerically positive definite (a floating structure); `rcond()` estimates 1/cond.
  explicit CholmodFactor(const Eigen::SparseMatrix<double>& A);
  ~CholmodFactor();
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  bool ok() const { return ok_; }
  double rcond() const { return rcond_; }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool ok_ = false;
  double rcond_ = 0.0;
};

}  // namespace rccm
