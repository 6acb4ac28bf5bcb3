#include "rccm/la/cholmod_factor.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/format.hpp"
#include "rccm/base/memory.hpp"
#include "rccm/la/blas_threads.hpp"

#include <Eigen/CholmodSupport>

#include <optional>

namespace rccm {

struct CholmodFactor::Impl {
  cholmod_common cm;
  cholmod_factor* L = nullptr;
  Impl() {
    cholmod_start(&cm);
    // No CHOLMOD warnings on stderr: a singular stiffness is reported by the caller (rcond)
    // with what to change, not as "matrix not positive definite".
    cm.print = 0;
    cm.error_handler = nullptr;
  }
  ~Impl() {
    cholmod_free_factor(&L, &cm);
    cholmod_finish(&cm);
  }
};

CholmodFactor::CholmodFactor(const Eigen::SparseMatrix<double>& A, const std::vector<int>& last)
    : impl_(std::make_unique<Impl>()) {
  const blas_threads::Wide wide;  // the factorization shares well among the BLAS's threads
  cholmod_common& cm = impl_->cm;
  cholmod_sparse a = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
  const int n = static_cast<int>(A.rows()), c = static_cast<int>(last.size());
  if (c == 0) {
    impl_->L = cholmod_analyze(&a, &cm);  // CHOLMOD's own choice of ordering
  } else {
    // Constrained AMD: set 0 (the others) first, set 1 (`last`) after; no postordering,
    // which could move the trailing indices.
    std::vector<int> member(n, 0), perm(n);
    for (int i : last) member[i] = 1;
    RCCM_VERIFY(cholmod_camd(&a, nullptr, 0, member.data(), perm.data(), &cm), "cholmod_camd");
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_GIVEN;
    cm.postorder = 0;
    impl_->L = cholmod_analyze_p(&a, perm.data(), nullptr, 0, &cm);
    trailing_order_.assign(perm.end() - c, perm.end());
    for (int i : trailing_order_) RCCM_VERIFY(member[i] == 1, "CAMD placed the constrained indices last");
  }
  // Too large to index with CHOLMOD's ints (2^31 entries), or no memory for its analysis.
  if (impl_->L == nullptr && (cm.status == CHOLMOD_TOO_LARGE || cm.status == CHOLMOD_OUT_OF_MEMORY))
    throw MemoryShortfall("the Cholesky factor of the body's stiffness (" + fmt("%.3g", n) + " unknowns) is " +
                          (cm.status == CHOLMOD_TOO_LARGE ? "too large for CHOLMOD (2^31 entries at most)"
                                                          : "more than the machine's memory holds (CHOLMOD's analysis)"));
  RCCM_VERIFY(impl_->L != nullptr, "cholmod_analyze");
  // The factor's size is known from the ordering: refused now rather than killed for memory
  // later (a 3D body's factor grows faster than its unknowns; the mesh's up-front estimate
  // cannot know the ordering).
  const cholmod_factor& L = *impl_->L;
  const double entries = L.is_super ? double(L.xsize) : cm.lnz;
  const std::string shortfall =
      memory_shortfall(8.0 * entries, "the Cholesky factor of the body's stiffness (" + fmt("%.3g", n) + " unknowns, " +
                                          fmt("%.3g", entries) + " entries in CHOLMOD's ordering)");
  if (!shortfall.empty()) throw MemoryShortfall(shortfall);
  cholmod_factorize(&a, impl_->L, &cm);
  ok_ = cm.status == CHOLMOD_OK && impl_->L->minor == impl_->L->n;
  if (!ok_) return;
  rcond_ = cholmod_rcond(impl_->L, &cm);
  // Column access for trailing_factor(): a simplicial, packed L L^T form (solves work the same).
  if (c > 0) RCCM_VERIFY(cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, impl_->L, &cm), "cholmod_change_factor");
}

CholmodFactor::~CholmodFactor() = default;

Eigen::MatrixXd CholmodFactor::solve(const Eigen::MatrixXd& b) const {
  if (b.cols() == 0) return Eigen::MatrixXd(b.rows(), 0);
  // A block of right-hand sides (W0's columns) shares among the BLAS's threads; one is a
  // run's small solve, for which they would only spin (blas_threads.hpp).
  std::optional<blas_threads::Wide> wide;
  if (b.cols() > 1) wide.emplace();
  // A view of b: cholmod_solve reads B and writes X.
  cholmod_dense B = Eigen::viewAsCholmod(const_cast<Eigen::MatrixXd&>(b));
  cholmod_dense* X = cholmod_solve(CHOLMOD_A, impl_->L, &B, &impl_->cm);
  RCCM_VERIFY(X != nullptr, "cholmod_solve");
  Eigen::MatrixXd x = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(X->x), b.rows(), b.cols());
  cholmod_free_dense(&X, &impl_->cm);
  return x;
}

Eigen::MatrixXd CholmodFactor::trailing_factor() const {
  const cholmod_factor& L = *impl_->L;
  const int n = static_cast<int>(L.n), c = static_cast<int>(trailing_order_.size()), first = n - c;
  const auto* p = static_cast<const int*>(L.p);
  const auto* i = static_cast<const int*>(L.i);
  const auto* x = static_cast<const double*>(L.x);
  Eigen::MatrixXd Lcc = Eigen::MatrixXd::Zero(c, c);
  for (int j = first; j < n; ++j)
    for (int k = p[j]; k < p[j + 1]; ++k) Lcc(i[k] - first, j - first) = x[k];  // rows >= j >= first
  return Lcc;
}

}  // namespace rccm
