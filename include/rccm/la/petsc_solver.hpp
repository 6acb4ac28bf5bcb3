// The body's sparse SPD matrix solved by PETSc over all processes of the run: each process
// holds a block of rows (MPIAIJ); MUMPS Cholesky (direct) or CG preconditioned by GAMG
// (iterative, to a relative residual). MUMPS may keep its factor on disk (out of core), and in
// one process forms the Schur complement on the interface's DOFs during its factorization, so
// W0 needs no solve of the body. Options of PETSc's own (-ksp_monitor, -pc_type hypre,
// -mat_mumps_icntl_*) pass through the PETSC_OPTIONS environment variable.
#pragma once

#include "rccm/la/spd_solver.hpp"

namespace rccm {

class PetscSolver : public SpdSolver {
 public:
  /// Collective: every process gives the same whole A (symmetric, both triangles) and keeps
  /// its own rows. `params.kind`: Mumps or CgGamg; `params.tolerance`: CG's relative residual;
  /// `params.out_of_core`: MUMPS writes its factor to disk. `last`: indices whose Schur
  /// complement MUMPS forms (one process, where it fits in memory; schur_factor()).
  PetscSolver(const SparseMatrix& A, const LinearSolverParams& params, const std::vector<int>& last = {});
  ~PetscSolver() override;
  PetscSolver(const PetscSolver&) = delete;
  PetscSolver& operator=(const PetscSolver&) = delete;

  bool ok() const override { return ok_; }
  double rcond() const override { return rcond_; }
  /// Collective; throws SolveError when CG does not reach the tolerance.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override;
  std::string name() const override;

  /// CG iterations of all solves so far (0 for MUMPS).
  long iterations() const { return iterations_; }

  /// The Cholesky factor L of the Schur complement S = A_CC - A_CI A_II^-1 A_IC on the indices
  /// C = `last` (rows and columns in that order), so (A^-1)_CC = (L L^T)^-1: in the lower
  /// triangle (the upper one keeps S's); nullptr where MUMPS did not form S (CG, several
  /// processes, no `last`, S beyond the memory).
  const Eigen::MatrixXd* schur_factor() const { return schur_factor_.size() ? &schur_factor_ : nullptr; }

 private:
  /// MUMPS's S into schur_factor_, factorized; false if S is not positive definite.
  bool take_schur_factor();

  struct Impl;
  std::unique_ptr<Impl> impl_;
  LinearSolver kind_;
  bool out_of_core_;
  bool ok_ = false;
  double rcond_ = 0.0;
  mutable long iterations_ = 0;
  Eigen::MatrixXd schur_factor_;
};

}  // namespace rccm
