// The body's sparse SPD matrix solved by PETSc over all processes of the run: each process
// holds a block of rows (MPIAIJ); MUMPS Cholesky (direct) or CG preconditioned by GAMG
// (iterative, to a relative residual). Options of PETSc's own (-ksp_monitor, -pc_type hypre,
// -mat_mumps_icntl_*) pass through the PETSC_OPTIONS environment variable.
#pragma once

#include "rccm/la/spd_solver.hpp"

namespace rccm {

class PetscSolver : public SpdSolver {
 public:
  /// Collective: every process gives the same whole A (symmetric, both triangles) and keeps
  /// its own rows. `kind`: Mumps or CgGamg; `tolerance`: CG's relative residual.
  PetscSolver(const SparseMatrix& A, LinearSolver kind, double tolerance);
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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  LinearSolver kind_;
  bool ok_ = false;
  double rcond_ = 0.0;
  mutable long iterations_ = 0;
};

}  // namespace rccm
