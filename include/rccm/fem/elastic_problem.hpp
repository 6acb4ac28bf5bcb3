// The linear elastic body with its Dirichlet DOFs eliminated and the initial interface
// springs added (docs/MODEL.md s4: K0 = K + sum_i P_i^T a_i diag(Ct, Cn) P_i), factorized once,
// by CHOLMOD with the interface DOFs ordered last so that the flexibility P K0^-1 P^T comes
// from the factor's trailing block (CholmodFactor), or by PETSc over the processes of the run
// (la/spd_solver.hpp), whose MUMPS gives the entries of K0^-1 on the interface DOFs in one
// process.
#pragma once

#include "rccm/la/cholmod_factor.hpp"
#include "rccm/la/petsc_solver.hpp"
#include "rccm/la/spd_solver.hpp"
#include "rccm/la/sparse.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace rccm {

class ElasticProblem {
 public:
  /// `springs`: full-size sparse matrix added to K before elimination (the interface
  /// springs at beta = 1); `prescribed`: the Dirichlet DOFs (Mesh::dof numbering);
  /// `interface_dofs`: the DOFs `flexibility()` will be asked about, ordered last (CHOLMOD)
  /// or on which K0^-1's entries are computed (MUMPS in one process);
  /// `linear`: who solves K0. Throws InputError when the body is not restrained (K0 singular).
  ElasticProblem(const SparseMatrix& K, const SparseMatrix& springs, std::vector<int> prescribed,
                 const std::vector<int>& interface_dofs = {}, const LinearSolverParams& linear = {});

  /// Full displacement for nodal forces f and prescribed values (full-size vectors;
  /// only the prescribed entries of `u_prescribed` are read): solves K0_FF u_F = f_F - K0_FD u_D.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& f, const Eigen::MatrixXd& u_prescribed) const;

  /// P K0^-1 P^T (prescribed displacements zero) for a P that reads only interface DOFs:
  /// with S = L_CC L_CC^T the Schur complement of the interface DOFs, (K0^-1)_CC = S^-1 and
  /// P K0^-1 P^T = G^T G with G = L_CC^-1 P_C^T: one dense triangular solve (docs/MODEL.md s4).
  /// From MUMPS's entries Z = (K0^-1)_CC: P_C Z P_C^T, two sparse products. Otherwise:
  /// flexibility_products() of the identity.
  Eigen::MatrixXd flexibility(const SparseMatrix& P) const;

  /// P K0^-1 P^T Y for a block of columns Y, the flexibility's products without forming it:
  /// P_C (K0^-1)_CC P_C^T Y from MUMPS's entries of the inverse, else by sparse solves (any
  /// ordering of the factor).
  Eigen::MatrixXd flexibility_products(const SparseMatrix& P, const Eigen::MatrixXd& Y) const;

  std::string solver_name() const { return solver_->name(); }

 private:
  /// Restriction of full-size columns to the free DOFs, and its transpose.
  Eigen::MatrixXd restrict_free(const Eigen::MatrixXd& full) const;
  Eigen::MatrixXd extend_free(const Eigen::MatrixXd& free) const;

  std::vector<int> free_, prescribed_;
  std::vector<int> free_index_;  // global DOF -> index among free DOFs, or -1
  SparseMatrix K0_FD_;
  std::unique_ptr<SpdSolver> solver_;
  /// P_C^T: the rows of P (columns) as forces on the free interface DOFs in `order` (rows).
  SparseMatrix interface_forces(const SparseMatrix& P, const std::vector<int>& order) const;

  std::vector<int> interface_free_;  // the free interface DOFs (free indices, sorted)
  const CholmodFactor* trailing_ = nullptr;  // solver_ when it ordered the interface DOFs last
  const Eigen::MatrixXd* inverse_ = nullptr;  // (K0^-1) on them, from MUMPS
};

}  // namespace rccm
