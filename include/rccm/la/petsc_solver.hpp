// The body's sparse SPD matrix solved by PETSc over all processes of the run: each process
// holds a block of rows (MPIAIJ); MUMPS Cholesky (direct) or CG preconditioned by GAMG
// (iterative, to a relative residual). MUMPS may keep its factor on disk (out of core), and in
// one process computes the entries of A^-1 on the interface's DOFs after its factorization (its
// ICNTL(30), pruned sparse solves), so W0 needs no solve of the body. Options of PETSc's own
// (-ksp_monitor, -pc_type hypre, -mat_mumps_icntl_*) pass through the PETSC_OPTIONS environment
// variable.
#pragma once

#include "rccm/la/spd_solver.hpp"

namespace rccm {

class PetscSolver : public SpdSolver {
 public:
  /// Collective: every process gives the same whole A (symmetric, both triangles) and keeps
  /// its own rows. `params.kind`: Mumps or CgGamg; `params.tolerance`: CG's relative residual;
  /// `params.out_of_core`: MUMPS writes its factor to disk. `last`: indices on which
  /// MUMPS computes A^-1's entries (one process, where they fit in memory; interface_inverse()).
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

  /// (A^-1)_CC on the indices C = `last` (rows and columns in that order); nullptr where MUMPS
  /// did not compute it (CG, several processes, no `last`, beyond the memory).
  const Eigen::MatrixXd* interface_inverse() const { return interface_inverse_.size() ? &interface_inverse_ : nullptr; }

 private:
  /// MUMPS's entries (A^-1)_CC into interface_inverse_.
  void take_interface_inverse(const std::vector<int>& last);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  LinearSolver kind_;
  bool out_of_core_;
  bool ok_ = false;
  double rcond_ = 0.0;
  mutable long iterations_ = 0;
  Eigen::MatrixXd interface_inverse_;
};

}  // namespace rccm
