// The linear elastic body with its Dirichlet DOFs eliminated and the initial interface
// springs added (MODEL.md s4: K0 = K + sum_i P_i^T a_i diag(Ct, Cn) P_i), factorized once.
#pragma once

#include "rccm/cholmod_factor.hpp"
#include "rccm/elasticity.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace rccm {

class ElasticProblem {
 public:
  /// `springs`: full-size sparse matrix added to K before elimination (the interface
  /// springs at beta = 1); `prescribed`: the Dirichlet DOFs (global numbering 2n + c).
  /// Throws InputError when the body is not restrained (K0 singular).
  ElasticProblem(const SparseMatrix& K, const SparseMatrix& springs, std::vector<int> prescribed);

  int num_dofs() const { return static_cast<int>(free_index_.size()); }
  const std::vector<int>& free_dofs() const { return free_; }
  const std::vector<int>& prescribed_dofs() const { return prescribed_; }
  double rcond() const { return factor_->rcond(); }

  /// Full displacement for nodal forces f and prescribed values (full-size vectors;
  /// only the prescribed entries of `u_prescribed` are read): solves K0_FF u_F = f_F - K0_FD u_D.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& f, const Eigen::MatrixXd& u_prescribed) const;

  /// Restriction of full-size columns to the free DOFs, and its transpose.
  Eigen::MatrixXd restrict_free(const Eigen::MatrixXd& full) const;
  Eigen::MatrixXd extend_free(const Eigen::MatrixXd& free) const;

 private:
  std::vector<int> free_, prescribed_;
  std::vector<int> free_index_;  // global DOF -> index among free DOFs, or -1
  SparseMatrix K0_FD_;
  std::unique_ptr<CholmodFactor> factor_;
};

}  // namespace rccm
