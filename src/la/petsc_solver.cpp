#include "rccm/la/petsc_solver.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/memory.hpp"
#include "rccm/la/parallel.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rccm {

namespace {

void check(PetscErrorCode e, const char* call) {
  if (e != 0) throw InternalError(std::string("PETSc: ") + call + " failed with error " + std::to_string(e));
}

/// MUMPS stopped for memory (`status` = INFOG(1): -19 over ICNTL(23), -9 and -13 out of
/// memory): said with its own estimate, INFOG(16) MB per process.
void refuse_if_short_of_memory(Mat factor, PetscInt status, PetscInt n) {
  PetscInt megabytes = 0;
  if (status != -19 && status != -9 && status != -13) return;
  check(MatMumpsGetInfog(factor, 16, &megabytes), "MatMumpsGetInfog");
  std::ostringstream m;
  m.precision(3);
  m << "the Cholesky factor of the body's stiffness by MUMPS (" << double(n) << " unknowns, " << parallel::size()
    << " process(es)) needs about " << 1e-3 * double(megabytes) << " GB per process, each has "
    << available_memory() / parallel::size() / 1e9 << " GB available";
  throw MemoryShortfall(m.str());
}

/// MUMPS failed otherwise than for memory or a singular matrix (`status` = INFOG(1) < 0): said
/// with its codes; out of core, the usual cause is the disk.
void refuse_if_failed(Mat factor, PetscInt status, bool out_of_core) {
  PetscInt detail = 0;
  if (status >= 0 || status == -10 || status == -40) return;  // -10, -40: singular, said by the caller
  check(MatMumpsGetInfog(factor, 2, &detail), "MatMumpsGetInfog");
  std::ostringstream m;
  m << "the factorization of the body's stiffness by MUMPS failed (INFOG(1) = " << status << ", INFOG(2) = " << detail
    << "; the MUMPS users' guide lists the codes)";
  if (out_of_core) {
    const char* dir = std::getenv("MUMPS_OOC_TMPDIR");
    m << "; out of core (solver.out_of_core) it writes its factor to " << (dir ? dir : "/tmp")
      << (dir ? " (MUMPS_OOC_TMPDIR)" : " (MUMPS_OOC_TMPDIR unset)")
      << ": check that this directory exists, is writable and has room for the factor";
  }
  throw SolveError(m.str());
}

}  // namespace

struct PetscSolver::Impl {
  Mat A = nullptr;
  KSP ksp = nullptr;
  Mat factor = nullptr;  // MUMPS's, owned by the preconditioner
  Vec b = nullptr, x = nullptr, x_all = nullptr;  // x_all: the whole solution on every process
  VecScatter to_all = nullptr;
  PetscInt lo = 0, hi = 0;  // this process's rows

  ~Impl() {
    VecScatterDestroy(&to_all);
    VecDestroy(&x_all);
    VecDestroy(&x);
    VecDestroy(&b);
    KSPDestroy(&ksp);
    MatDestroy(&A);
  }

  /// KSP's solution of b's rows [lo, hi) of column `rhs`, whole, into `out`; the KSP's reason.
  KSPConvergedReason solve_column(const double* rhs, double* out) const {
    PetscScalar* local = nullptr;
    check(VecGetArray(b, &local), "VecGetArray");
    std::copy(rhs + lo, rhs + hi, local);
    check(VecRestoreArray(b, &local), "VecRestoreArray");
    check(KSPSolve(ksp, b, x), "KSPSolve");
    KSPConvergedReason reason;
    check(KSPGetConvergedReason(ksp, &reason), "KSPGetConvergedReason");
    gather(x, out);
    return reason;
  }

  /// KSPMatSolve on the columns of b at once (for MUMPS: one solve phase), whole into x.
  void solve_block(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& out) const {
    const PetscInt n = static_cast<PetscInt>(rhs.rows()), k = static_cast<PetscInt>(rhs.cols());
    Mat B = nullptr, X = nullptr;
    check(MatCreateDense(PETSC_COMM_WORLD, hi - lo, PETSC_DECIDE, n, k, nullptr, &B), "MatCreateDense");
    check(MatCreateDense(PETSC_COMM_WORLD, hi - lo, PETSC_DECIDE, n, k, nullptr, &X), "MatCreateDense");
    PetscScalar* local = nullptr;
    PetscInt lda = 0;
    check(MatDenseGetLDA(B, &lda), "MatDenseGetLDA");
    check(MatDenseGetArrayWrite(B, &local), "MatDenseGetArrayWrite");
    for (PetscInt c = 0; c < k; ++c) std::copy(rhs.col(c).data() + lo, rhs.col(c).data() + hi, local + c * lda);
    check(MatDenseRestoreArrayWrite(B, &local), "MatDenseRestoreArrayWrite");
    check(KSPMatSolve(ksp, B, X), "KSPMatSolve");
    for (PetscInt c = 0; c < k; ++c) {
      Vec column = nullptr;
      check(MatDenseGetColumnVecRead(X, c, &column), "MatDenseGetColumnVecRead");
      gather(column, out.col(c).data());
      check(MatDenseRestoreColumnVecRead(X, c, &column), "MatDenseRestoreColumnVecRead");
    }
    MatDestroy(&X);
    MatDestroy(&B);
  }

  /// The whole of a distributed vector v, on every process, into out.
  void gather(Vec v, double* out) const {
    check(VecScatterBegin(to_all, v, x_all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
    check(VecScatterEnd(to_all, v, x_all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
    const PetscScalar* whole = nullptr;
    PetscInt n = 0;
    check(VecGetSize(x_all, &n), "VecGetSize");
    check(VecGetArrayRead(x_all, &whole), "VecGetArrayRead");
    std::copy(whole, whole + n, out);
    check(VecRestoreArrayRead(x_all, &whole), "VecRestoreArrayRead");
  }
};

PetscSolver::PetscSolver(const SparseMatrix& A, const LinearSolverParams& params, const std::vector<int>& last)
    : impl_(std::make_unique<Impl>()), kind_(params.kind), out_of_core_(params.kind == LinearSolver::Mumps && params.out_of_core) {
  const LinearSolver kind = params.kind;
  RCCM_VERIFY(kind == LinearSolver::Mumps || kind == LinearSolver::CgGamg, "PetscSolver: MUMPS or CG + GAMG");
  parallel::start();
  Impl& p = *impl_;
  PetscInt n = static_cast<PetscInt>(A.rows()), local = PETSC_DECIDE;
  check(PetscSplitOwnership(PETSC_COMM_WORLD, &local, &n), "PetscSplitOwnership");
  check(MPI_Scan(&local, &p.hi, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD), "MPI_Scan");
  p.lo = p.hi - local;

  // This process's rows: by symmetry, A's columns lo..hi-1 (column-major storage).
  std::vector<PetscInt> diagonal_block(local, 0), off_block(local, 0);
  for (PetscInt r = p.lo; r < p.hi; ++r)
    for (SparseMatrix::InnerIterator it(A, r); it; ++it)
      ++(it.row() >= p.lo && it.row() < p.hi ? diagonal_block : off_block)[r - p.lo];
  check(MatCreate(PETSC_COMM_WORLD, &p.A), "MatCreate");
  check(MatSetSizes(p.A, local, local, n, n), "MatSetSizes");
  check(MatSetType(p.A, MATAIJ), "MatSetType");
  check(MatXAIJSetPreallocation(p.A, 1, diagonal_block.data(), off_block.data(), nullptr, nullptr),
        "MatXAIJSetPreallocation");
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> values;
  for (PetscInt r = p.lo; r < p.hi; ++r) {
    cols.clear();
    values.clear();
    for (SparseMatrix::InnerIterator it(A, r); it; ++it) {
      cols.push_back(static_cast<PetscInt>(it.row()));
      values.push_back(it.value());
    }
    check(MatSetValues(p.A, 1, &r, static_cast<PetscInt>(cols.size()), cols.data(), values.data(), INSERT_VALUES),
          "MatSetValues");
  }
  check(MatAssemblyBegin(p.A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(p.A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  check(MatSetOption(p.A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");

  check(KSPCreate(PETSC_COMM_WORLD, &p.ksp), "KSPCreate");
  check(KSPSetOperators(p.ksp, p.A, p.A), "KSPSetOperators");
  bool inverse = false;  // MUMPS computes the entries (A^-1)_CC, C = `last`
  PC pc;
  check(KSPGetPC(p.ksp, &pc), "KSPGetPC");
  if (kind == LinearSolver::Mumps) {
    check(KSPSetType(p.ksp, KSPPREONLY), "KSPSetType");
    check(PCSetType(pc, PCCHOLESKY), "PCSetType");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
    check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
    check(PCFactorGetMatrix(pc, &p.factor), "PCFactorGetMatrix");
    // MUMPS refuses a factorization whose analysis needs more working memory than each
    // process may take (ICNTL(23), MB), instead of being killed for memory while it runs; no
    // cap where the memory is unknown (available_memory()'s 1e18 bytes: 1e12 MB).
    const double per_process = available_memory() / parallel::size() / 1e6;
    if (per_process < 1e9) check(MatMumpsSetIcntl(p.factor, 23, static_cast<PetscInt>(std::max(1.0, per_process))), "MatMumpsSetIcntl");
    if (params.out_of_core) check(MatMumpsSetIcntl(p.factor, 22, 1), "MatMumpsSetIcntl");
    // The entries (A^-1)_CC on `last` (dense, c x c), asked of MUMPS after its factorization.
    // One process only (PETSc's support), and where they take at most a quarter of the memory:
    // 20 c^2 bytes while they are computed (the request's pattern and values, then ours).
    const double c = double(last.size());
    inverse = !last.empty() && parallel::size() == 1 && 20 * c * c <= available_memory() / 4;
  } else {
    check(KSPSetType(p.ksp, KSPCG), "KSPSetType");
    check(PCSetType(pc, PCGAMG), "PCSetType");
    check(KSPSetNormType(p.ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");  // the residual itself
    check(KSPSetTolerances(p.ksp, params.tolerance, 1e-300, PETSC_DEFAULT, 100000), "KSPSetTolerances");
  }
  check(KSPSetFromOptions(p.ksp), "KSPSetFromOptions");  // PETSC_OPTIONS
  check(KSPSetUp(p.ksp), "KSPSetUp");                     // MUMPS factorizes here
  if (kind == LinearSolver::Mumps) {
    PetscInt status = 0;  // INFOG(1): < 0 where the factorization failed
    check(MatMumpsGetInfog(p.factor, 1, &status), "MatMumpsGetInfog");
    refuse_if_short_of_memory(p.factor, status, n);
    refuse_if_failed(p.factor, status, params.out_of_core);
    if (status < 0) return;  // singular: not ok
  }
  check(MatCreateVecs(p.A, &p.x, &p.b), "MatCreateVecs");
  check(VecScatterCreateToAll(p.x, &p.to_all, &p.x_all), "VecScatterCreateToAll");

  // Positive definite? A failed factorization (a zero pivot) or a floating structure shows in
  // the residual of a solve whose right-hand side has a part in every direction.
  Eigen::VectorXd rhs(n), x(n);
  for (PetscInt i = 0; i < n; ++i) rhs[i] = 1.0 + 0.5 * std::sin(1.3 * static_cast<double>(i));
  const KSPConvergedReason reason = p.solve_column(rhs.data(), x.data());
  const double residual = (A * x - rhs).norm() / rhs.norm();
  ok_ = reason >= 0 && residual <= std::max(1e-8, 10 * params.tolerance);  // false for NaN too
  if (!ok_) return;
  const Eigen::VectorXd d = Eigen::VectorXd(A.diagonal()).cwiseAbs();
  rcond_ = d.minCoeff() / d.maxCoeff();
  if (inverse) take_interface_inverse(last);
}

PetscSolver::~PetscSolver() = default;

void PetscSolver::take_interface_inverse(const std::vector<int>& last) {
  // MUMPS's entries of the inverse (ICNTL(30)): a sparse right-hand side per column of C, the
  // forward solve pruned to the factor's paths from C to the root, the backward one to C.
  const Impl& p = *impl_;
  PetscInt n = 0;
  check(MatGetSize(p.A, &n, nullptr), "MatGetSize");
  const PetscInt c = static_cast<PetscInt>(last.size());
  std::vector<PetscInt> per_row(n, 0), columns(last.begin(), last.end());
  for (int i : last) per_row[i] = c;
  Mat entries = nullptr;  // the pattern C x C asked for, then the entries
  check(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, per_row.data(), &entries), "MatCreateSeqAIJ");
  const std::vector<PetscScalar> zeros(c, 0.0);
  for (PetscInt row : columns)
    check(MatSetValues(entries, 1, &row, c, columns.data(), zeros.data(), INSERT_VALUES), "MatSetValues");
  check(MatAssemblyBegin(entries, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(entries, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  // Columns of C per pass over the factor (ICNTL(27)), each 8 n bytes of MUMPS's work: 256 in
  // core (33 s at c = 6348, n = 10^5, against 46 s by MUMPS's own 32 and 36 s by 2048); out of
  // core, where each pass reads the factor from disk, as many as a quarter of the memory holds.
  const double columns_in_memory = available_memory() / 4 / (8.0 * double(n));
  const PetscInt block = out_of_core_ ? PetscInt(std::clamp(columns_in_memory, 256.0, 4096.0)) : 256;
  PetscInt default_block = 0;
  check(MatMumpsGetIcntl(p.factor, 27, &default_block), "MatMumpsGetIcntl");
  check(MatMumpsSetIcntl(p.factor, 27, block), "MatMumpsSetIcntl");
  check(MatMumpsGetInverseTranspose(p.factor, entries), "MatMumpsGetInverseTranspose");
  check(MatMumpsSetIcntl(p.factor, 30, 0), "MatMumpsSetIcntl");  // the later solves: whole ones
  check(MatMumpsSetIcntl(p.factor, 27, default_block), "MatMumpsSetIcntl");
  interface_inverse_.resize(c, c);
  for (PetscInt k = 0; k < c; ++k) {
    PetscInt count = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* values = nullptr;
    check(MatGetRow(entries, columns[k], &count, &cols, &values), "MatGetRow");
    RCCM_VERIFY(count == c, "MUMPS's inverse entries: one per column of C");
    std::copy(values, values + c, interface_inverse_.col(k).data());  // symmetric: row k as column k
    check(MatRestoreRow(entries, columns[k], &count, &cols, &values), "MatRestoreRow");
  }
  MatDestroy(&entries);
}

Eigen::MatrixXd PetscSolver::solve(const Eigen::MatrixXd& b) const {
  Eigen::MatrixXd x(b.rows(), b.cols());
  if (kind_ == LinearSolver::Mumps && b.cols() > 1) {  // MUMPS's solve phase on all columns at once
    impl_->solve_block(b, x);
    return x;
  }
  for (Eigen::Index c = 0; c < b.cols(); ++c) {
    const KSPConvergedReason reason = impl_->solve_column(b.col(c).data(), x.col(c).data());
    PetscInt its = 0;
    check(KSPGetIterationNumber(impl_->ksp, &its), "KSPGetIterationNumber");
    iterations_ += its;
    if (reason < 0) {
      std::ostringstream m;
      m << "the body's solve by " << name() << " stopped without converging (PETSc reason " << reason << " after "
        << its << " iterations); loosen solver.linear_tolerance or use solver.linear = \"mumps\"";
      throw SolveError(m.str());
    }
  }
  return x;
}

std::string PetscSolver::name() const {
  const int procs = parallel::size();
  std::string name = std::string(kind_ == LinearSolver::Mumps ? "PETSc MUMPS" : "PETSc CG + GAMG") + " on " +
                     std::to_string(procs) + (procs == 1 ? " process" : " processes");
  if (out_of_core_) name += ", out of core";
  if (interface_inverse_.size())
    name += ", with the inverse's entries on " + std::to_string(interface_inverse_.rows()) + " interface DOFs";
  return name;
}

}  // namespace rccm
