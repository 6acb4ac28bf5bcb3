// Hierarchically off-diagonal low-rank (HODLR) matrices and their direct solver
// (Ambikasaran and Darve, J. Sci. Comput. 57, 2013): the index range is bisected recursively
// down to small dense leaves, and each off-diagonal block of a bisection is kept as a
// product U V^T of rank r. The flexibility W0 of an interface line is such a matrix: its
// off-diagonal blocks have rank 15-20 at 1e-14 of |W0| on the refined B1 family
// (docs/PERFORMANCE.md), so that a solve with the exact step's matrix costs about
// m r log m instead of m^2, and a factorization m r^2 log^2 m instead of m^3.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

#include <functional>
#include <memory>
#include <vector>

namespace rccm {

/// A Gauss-Seidel pass by blocks of neighbouring unknowns, each block passed over `sweeps`
/// times before the next (a block Gauss-Seidel pass whose blocks are solved by inner sweeps:
/// what couples them most is inside, and their part of the matrix stays in the cache). The
/// blocks have at most `rows` rows (a HODLR matrix: its largest subtrees of at most that many,
/// a leaf at least). One sweep: the plain pass.
struct SweepBlocks {
  int sweeps = 1;
  Eigen::Index rows = 0;
};

class HodlrMatrix {
 public:
  /// Compresses the square matrix A: leaves of at most `leaf_size` rows, bisections at
  /// multiples of `granule` (a contact pair's rows stay in one block), off-diagonal blocks
  /// to an absolute accuracy of `tolerance` (a randomized range finder, deterministic seed).
  HodlrMatrix(const Eigen::MatrixXd& A, double tolerance, int leaf_size, int granule);
  /// Products A X of a matrix for a block of columns X.
  using Products = std::function<Eigen::MatrixXd(const Eigen::MatrixXd& X)>;
  /// Compresses the symmetric matrix A known only by its products, never formed (peeling:
  /// about (r log m + leaf_size) columns of products in blocks of a few, r the blocks'
  /// rank): leaves and bisections as above, off-diagonal blocks to `relative_tolerance` of
  /// A's largest diagonal entry, each pair of blocks A(first, second) = A(second, first)^T
  /// stored once.
  static HodlrMatrix symmetric(Eigen::Index size, const Products& A, double relative_tolerance, int leaf_size,
                               int granule);
  ~HodlrMatrix();
  HodlrMatrix(HodlrMatrix&&) noexcept;
  HodlrMatrix& operator=(HodlrMatrix&&) noexcept;

  Eigen::Index size() const { return size_; }
  int granule() const { return granule_; }
  /// The matrix C_y + C_w A for block-diagonal C_w, C_y with blocks of the granule's size,
  /// given side by side (granule x size): the off-diagonal blocks keep their ranks, only the
  /// leaves and the left factors U change (m r work, no recompression).
  HodlrMatrix rows_mixed(const Eigen::MatrixXd& Cw, const Eigen::MatrixXd& Cy) const;
  /// This matrix, mixed from A by rows_mixed, mixed again from Cw and Cy on the granules that
  /// begin at the given rows only (about g (leaf + r log m) work per granule).
  void remix_rows(const HodlrMatrix& A, const Eigen::MatrixXd& Cw, const Eigen::MatrixXd& Cy,
                  const std::vector<Eigen::Index>& granules);
  /// y = A x.
  Eigen::VectorXd multiply(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  /// A X for a block of columns (a product of BLAS-3 speed).
  Eigen::MatrixXd multiply_block(const Eigen::Ref<const Eigen::MatrixXd>& X) const;
  /// A Gauss-Seidel pass in the order of the granules: visit(first) changes x's granule at
  /// `first` (reading y's), and y keeps up with it: on entry to each visit y holds
  /// A x + (y - A x at the pass's start) on that granule, and after the pass everywhere.
  /// Costs m r log m per pass (the leaves' columns, then each bisection's blocks once), and
  /// `blocks`' subtrees again for each of their further sweeps.
  void gauss_seidel(const std::function<void(Eigen::Index first)>& visit, const Eigen::VectorXd& x,
                    Eigen::VectorXd& y, const SweepBlocks& blocks = {}) const;
  /// The diagonal block A(first .. first + n - 1, same), within one leaf (a granule's block).
  Eigen::MatrixXd diagonal_block(Eigen::Index first, Eigen::Index n) const;
  /// The largest magnitude on the diagonal.
  double diagonal_scale() const;
  /// This matrix with each off-diagonal block recompressed to `relative_tolerance` of the
  /// largest diagonal entry (an SVD of its factors' small core; no products): lower ranks,
  /// for a factorization that refinement with this matrix corrects.
  HodlrMatrix truncated(double relative_tolerance) const;
  /// This matrix plus X Y^T (X, Y with this size's rows): the leaves added to, each
  /// off-diagonal block's factors extended by X's and Y's rows and recompressed as truncated()
  /// does, no products: a change of low rank (W0 when a few pairs' springs change,
  /// Condensation::change_springs) for about m (r + k)^2 log m, k = X's columns. A matrix
  /// from symmetric() stays symmetric, its blocks stored once: X Y^T must be symmetric too
  /// (A G A^T with G symmetric), as only its blocks below the diagonal are added.
  HodlrMatrix plus(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y, double relative_tolerance) const;
  /// The largest rank of an off-diagonal block, and the doubles stored.
  int max_rank() const;
  Eigen::Index stored() const;

  struct Node;  // a diagonal block: a dense leaf, or two children and the blocks between them

 private:
  friend class HodlrSolver;
  HodlrMatrix() = default;
  std::unique_ptr<Node> root_;
  Eigen::Index size_ = 0;
  int granule_ = 1;
};

/// The factorization of a HodlrMatrix: dense LU at the leaves, and at each bisection the
/// Sherman-Morrison-Woodbury formula for the two off-diagonal blocks.
class HodlrSolver {
 public:
  explicit HodlrSolver(const HodlrMatrix& A);
  ~HodlrSolver();
  HodlrSolver(HodlrSolver&&) noexcept;
  HodlrSolver& operator=(HodlrSolver&&) noexcept;

  /// The factorization of A, a matrix of the factorized one's shape that differs from it in
  /// the given rows (sorted) only: the leaves and bisections that hold none keep theirs
  /// (a change within one leaf costs about m r log m instead of m r^2 log^2 m).
  void refactorize(const HodlrMatrix& A, const std::vector<Eigen::Index>& rows);
  /// A^-1 B (B's columns); not finite when A (or one of its diagonal blocks) is singular.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

  struct Node;

 private:
  std::unique_ptr<Node> root_;
};

}  // namespace rccm
