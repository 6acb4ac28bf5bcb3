// A factorized (or preconditioned) sparse symmetric positive definite matrix that solves
// blocks of right-hand sides: CHOLMOD (the embedded default, one process), or PETSc with MUMPS
// (direct) or CG + GAMG (iterative), distributed over the processes of an mpirun run
// (la/parallel.hpp) with the whole solution returned to every process.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/la/sparse.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace rccm {

class SpdSolver {
 public:
  virtual ~SpdSolver() = default;
  /// False when A is not numerically positive definite (a floating structure).
  virtual bool ok() const = 0;
  /// An estimate of 1 / cond(A): CHOLMOD's, or for PETSc the spread of A's diagonal; 0 if not ok.
  virtual double rcond() const = 0;
  /// A^-1 b for every column of b, whole vectors on every process (collective under mpirun).
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const = 0;
  /// Who solves, for messages and reports: "CHOLMOD", "PETSc MUMPS on 2 processes", ...
  virtual std::string name() const = 0;
};

/// The solver `kind` stands for: Auto is CHOLMOD in one process, MUMPS in several (under
/// mpirun); any other kind is itself.
LinearSolver chosen_linear_solver(LinearSolver kind);

/// The solver of `params.kind` (chosen_linear_solver) for A (symmetric, both triangles stored).
/// `last`: indices ordered last (CholmodFactor), or on which MUMPS computes A^-1's entries (PetscSolver).
std::unique_ptr<SpdSolver> make_spd_solver(const SparseMatrix& A, const LinearSolverParams& params,
                                           const std::vector<int>& last = {});

}  // namespace rccm
