#include "rccm/la/spd_solver.hpp"

#include "rccm/la/cholmod_factor.hpp"
#include "rccm/la/parallel.hpp"
#include "rccm/la/petsc_solver.hpp"

namespace rccm {

LinearSolver chosen_linear_solver(LinearSolver kind) {
  if (kind == LinearSolver::Auto) kind = parallel::size() > 1 ? LinearSolver::Mumps : LinearSolver::Cholmod;
  return kind;
}

std::unique_ptr<SpdSolver> make_spd_solver(const SparseMatrix& A, const LinearSolverParams& params,
                                           const std::vector<int>& last) {
  const LinearSolver kind = chosen_linear_solver(params.kind);
  if (kind == LinearSolver::Cholmod) return std::make_unique<CholmodFactor>(A, last);
  LinearSolverParams chosen = params;
  chosen.kind = kind;
  return std::make_unique<PetscSolver>(A, chosen, last);
}

}  // namespace rccm
