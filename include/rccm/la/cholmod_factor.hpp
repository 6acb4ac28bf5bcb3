// One Cholesky factorization P A P^T = L L^T of a sparse SPD matrix by SuiteSparse CHOLMOD.
// Optionally a set of indices is ordered last (constrained AMD): the trailing block L_CC of
// the factor is then the Cholesky factor of their Schur complement S = A_CC - A_CI A_II^-1 A_IC,
// so (A^-1)_CC = S^-1 costs one dense triangular inverse instead of one solve per index.
#pragma once

#include "rccm/la/spd_solver.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace rccm {

class CholmodFactor : public SpdSolver {
 public:
  /// Factorizes A (symmetric; both triangles stored) with the indices `last` ordered after
  /// all the others. `ok()` is false when A is not numerically positive definite (a floating
  /// structure); `rcond()` estimates 1/cond.
  explicit CholmodFactor(const Eigen::SparseMatrix<double>& A, const std::vector<int>& last = {});
  ~CholmodFactor() override;
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  bool ok() const override { return ok_; }
  double rcond() const override { return rcond_; }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override;
  std::string name() const override { return "CHOLMOD"; }

  /// The lower-triangular trailing block L_CC (dense), its rows and columns being the
  /// indices of `trailing_order()`: the `last` indices in the factor's order.
  Eigen::MatrixXd trailing_factor() const;
  const std::vector<int>& trailing_order() const { return trailing_order_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool ok_ = false;
  double rcond_ = 0.0;
  std::vector<int> trailing_order_;
};

}  // namespace rccm
