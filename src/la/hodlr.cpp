#include "rccm/la/hodlr.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/la/blas_threads.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <omp.h>

#include <algorithm>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace rccm {

struct HodlrMatrix::Node {
  Eigen::Index begin = 0, end = 0;
  Eigen::MatrixXd dense;                  // a leaf's block
  std::unique_ptr<Node> first, second;    // the halves of a bisection
  // A(second, first) = U21 V21^T and A(first, second) = U12 V12^T, where on a symmetric matrix
  // (`mirrored`) U12 = V21 and V12 = U21 are not stored again: half the memory and traffic.
  Eigen::MatrixXd U21, V21, U12_own, V12_own;
  bool mirrored = false;
  const Eigen::MatrixXd& U12() const { return mirrored ? V21 : U12_own; }
  const Eigen::MatrixXd& V12() const { return mirrored ? U21 : V12_own; }
  bool leaf() const { return !first; }
};

namespace {

/// Y -= Q Q^T Y, twice: orthogonal to Q to round-off.
void orthogonalize(const Eigen::MatrixXd& Q, Eigen::Ref<Eigen::MatrixXd> Y) {
  for (int pass = 0; pass < 2; ++pass) Y -= Q * (Q.transpose() * Y);
}

/// Q grows by at most `add` orthonormal columns spanning Y's range (Y already orthogonal to Q)
/// above `floor`; returns how many. Directions of Y below the floor are round-off: a block of
/// lower rank than min(rows, cols) (W0's zero rows and columns where a support holds a contact
/// node) has no more range, and a basis grown from them was not orthogonal to Q (W0 compressed
/// 3.5 % off on such an interface).
Eigen::Index grow_basis(Eigen::MatrixXd& Q, const Eigen::MatrixXd& Y, Eigen::Index add, double floor) {
  const Eigen::Index n1 = Y.rows();
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Y);
  const Eigen::MatrixXd R = qr.matrixR().template triangularView<Eigen::Upper>();
  Eigen::Index rank = 0;
  while (rank < std::min(add, R.cols()) && std::abs(R(rank, rank)) > floor) ++rank;
  if (rank == 0) return 0;
  Eigen::MatrixXd basis = qr.householderQ() * Eigen::MatrixXd::Identity(n1, rank);
  orthogonalize(Q, basis);  // Y's round-off is not orthogonal to Q
  basis = Eigen::HouseholderQR<Eigen::MatrixXd>(basis).householderQ() * Eigen::MatrixXd::Identity(n1, rank);
  Q.conservativeResize(n1, Q.cols() + rank);
  Q.rightCols(rank) = basis;
  return rank;
}

/// B ~ Q Vq^T (Vq = B^T Q) truncated to U V^T by the SVD of the small factor, keeping the
/// singular values whose tail exceeds `tolerance` / 2.
void truncate(const Eigen::MatrixXd& Q, const Eigen::MatrixXd& Vq, double tolerance, Eigen::MatrixXd& U,
              Eigen::MatrixXd& V) {
  if (Q.cols() == 0) {  // B below the tolerance: rank zero
    U.resize(Q.rows(), 0), V.resize(Vq.rows(), 0);
    return;
  }
  // Jacobi, not BDCSVD: Eigen 3.4's BDCSVD lost 1e-6 of |B| on W0's blocks (singular values
  // falling to 1e-9 of the largest). Vq has Q's columns, few on low-rank blocks (on a block
  // of full rank Jacobi is slower, and the compression pointless anyway).
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Vq, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  Eigen::Index rank = s.size();
  double tail = 0;
  while (rank > 0 && tail + s[rank - 1] * s[rank - 1] <= 0.25 * tolerance * tolerance)
    tail += s[rank - 1] * s[rank - 1], --rank;
  U = Q * svd.matrixV().leftCols(rank) * s.head(rank).asDiagonal();
  V = svd.matrixU().leftCols(rank);
}

constexpr int probes = 8;  // random probes per round of a range finder

/// One block's range finder (Halko, Martinsson and Tropp, SIAM Rev. 53, 2011, alg. 4.2): an
/// orthonormal basis Q of B's range grown by rounds of random probes B omega until the
/// probes' residual is below the tolerance.
struct RangeFinder {
  Eigen::MatrixXd Q;
  Eigen::Index full;       // min(rows, cols): no more basis than that
  double floor = 0;        // round-off of B's products: no basis is grown from it
  double previous = 0;     // the last round's residual
  bool done = false;

  RangeFinder(Eigen::Index rows, Eigen::Index full) : Q(rows, 0), full(full) { done = full == 0; }

  /// Takes a round's products Y = B omega (overwritten); done when they are within the
  /// tolerance of Q's span. `noisy`: the products carry the errors of other blocks'
  /// compressions (peeling), so a residual that stops falling near the tolerance is noise.
  void take(Eigen::Ref<Eigen::MatrixXd> Y, double tolerance, bool noisy) {
    if (Q.cols() == 0) floor = 1e-14 * Y.colwise().norm().maxCoeff();
    orthogonalize(Q, Y);
    // E |M w|^2 = |M|_F^2 for a Gaussian w; the largest of `probes` samples, with a margin of 10.
    const double residual = Y.colwise().norm().maxCoeff();
    const bool stalled = noisy && Q.cols() > 0 && residual <= 100 * tolerance && residual > 0.5 * previous;
    previous = residual;
    if (10.0 * residual <= std::max(tolerance, floor) || stalled) {
      done = true;
      return;
    }
    const Eigen::Index add = std::min<Eigen::Index>(Y.cols(), full - Q.cols());
    done = grow_basis(Q, Y, add, floor) == 0 || Q.cols() == full;
  }
};

void gaussian(Eigen::Ref<Eigen::MatrixXd> omega, std::mt19937& rng) {
  std::normal_distribution<double> gauss;
  for (Eigen::Index j = 0; j < omega.cols(); ++j)
    for (Eigen::Index i = 0; i < omega.rows(); ++i) omega(i, j) = gauss(rng);
}

/// B ~ U V^T with |B - U V^T|_F <= tolerance (with high probability).
void compress(const Eigen::Ref<const Eigen::MatrixXd>& B, double tolerance, std::mt19937& rng, Eigen::MatrixXd& U,
              Eigen::MatrixXd& V) {
  RangeFinder range(B.rows(), std::min(B.rows(), B.cols()));
  Eigen::MatrixXd omega(B.cols(), probes);
  while (!range.done) {
    gaussian(omega, rng);
    Eigen::MatrixXd Y = B * omega;
    range.take(Y, tolerance, false);
  }
  truncate(range.Q, B.transpose() * range.Q, tolerance, U, V);
}

/// The bisections down to leaves of at most `leaf_size` rows, at multiples of `granule`; no blocks yet.
std::unique_ptr<HodlrMatrix::Node> bisections(Eigen::Index begin, Eigen::Index end, int leaf_size, int granule) {
  auto node = std::make_unique<HodlrMatrix::Node>();
  node->begin = begin, node->end = end;
  const Eigen::Index n = end - begin, mid = begin + (n / 2 / granule) * granule;
  if (n <= leaf_size || mid == begin) return node;
  node->first = bisections(begin, mid, leaf_size, granule);
  node->second = bisections(mid, end, leaf_size, granule);
  return node;
}

/// The nodes `depth` levels below `node`: its bisections (`leaves` false) or leaves.
void collect(HodlrMatrix::Node& node, int depth, bool leaves, std::vector<HodlrMatrix::Node*>& out) {
  if (node.leaf()) {
    if (leaves) out.push_back(&node);
    return;
  }
  if (depth == 0 && !leaves) {
    out.push_back(&node);
    return;
  }
  collect(*node.first, depth - 1, leaves, out);
  collect(*node.second, depth - 1, leaves, out);
}

/// Y -= (the off-diagonal blocks of the bisections less than `depth` levels below `node`) X:
/// what the levels already compressed contribute to the products.
void subtract_coarse(const HodlrMatrix::Node& node, int depth, const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) {
  if (node.leaf() || depth == 0) return;
  const HodlrMatrix::Node &a = *node.first, &b = *node.second;
  const Eigen::Index n1 = a.end - a.begin, n2 = b.end - b.begin;
  Y.middleRows(a.begin, n1).noalias() -= node.U12() * (node.V12().transpose() * X.middleRows(b.begin, n2));
  Y.middleRows(b.begin, n2).noalias() -= node.U21 * (node.V21.transpose() * X.middleRows(a.begin, n1));
  subtract_coarse(a, depth - 1, X, Y);
  subtract_coarse(b, depth - 1, X, Y);
}

/// The entries of a block each thread of its product with a vector gets at least: fewer, and
/// the threads' start and barrier cost more than they save (blocks of 2^15 entries and more in
/// two threads: the 2116-node peel's W0 a pass 1.6-1.7 times as fast, docs/PERFORMANCE.md "The
/// sweeps in threads"); many cores share a large block only.
constexpr Eigen::Index entries_per_thread = 1 << 14;

/// [begin, begin + count) of `n` items: thread `t` of `threads`'s share.
std::pair<Eigen::Index, Eigen::Index> share(Eigen::Index n, int t, int threads) {
  const Eigen::Index begin = n * t / threads;
  return {begin, n * (t + 1) / threads - begin};
}

/// y += U (V^T x), a block's product with a vector (a sweep streams the blocks from memory, so
/// a large one is cut into blas_threads::slices() slices, V^T x by columns, then U z by rows,
/// which blas_threads::products() threads share: the same sums whatever the threads), or with
/// a block of columns (BLAS-3 speed already).
template <class Columns>
void add_block_product(const Eigen::MatrixXd& U, const Eigen::MatrixXd& V, const Eigen::Ref<const Columns>& x,
                       Eigen::Ref<Columns> y) {
  const int slices = Columns::ColsAtCompileTime == 1
                         ? int(std::min<Eigen::Index>(blas_threads::slices(), U.size() / entries_per_thread))
                         : 1;
  if (slices <= 1) {
    y.noalias() += U * (V.transpose() * x);
    return;
  }
  const int threads = std::min(blas_threads::products(), slices);
  Columns z(V.cols(), 1);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    const int t = omp_get_thread_num(), n = omp_get_num_threads();
    for (int k = t; k < slices; k += n) {
      const auto [c, nc] = share(V.cols(), k, slices);
      z.middleRows(c, nc).noalias() = V.middleCols(c, nc).transpose() * x;
    }
#pragma omp barrier
    for (int k = t; k < slices; k += n) {
      const auto [r, nr] = share(U.rows(), k, slices);
      y.middleRows(r, nr).noalias() += U.middleRows(r, nr) * z;
    }
  }
}

/// A x for a vector or a block of columns x (Columns: Eigen::VectorXd or Eigen::MatrixXd).
template <class Columns>
Columns multiply(const HodlrMatrix::Node& node, const Eigen::Ref<const Columns>& x) {
  if (node.leaf()) return node.dense * x;
  const Eigen::Index n1 = node.first->end - node.first->begin, n2 = node.end - node.begin - n1;
  Columns y(x.rows(), x.cols());
  y.topRows(n1) = multiply<Columns>(*node.first, x.topRows(n1));
  add_block_product<Columns>(node.U12(), node.V12(), x.bottomRows(n2), y.topRows(n1));
  y.bottomRows(n2) = multiply<Columns>(*node.second, x.bottomRows(n2));
  add_block_product<Columns>(node.U21, node.V21, x.topRows(n1), y.bottomRows(n2));
  return y;
}

/// U V^T recompressed to Ut Vt within `tolerance`: U = Q R, then the SVD of the small factor
/// V R^T truncates it (truncate). U may have more columns than rows.
void recompress(const Eigen::MatrixXd& U, const Eigen::MatrixXd& V, double tolerance, Eigen::MatrixXd& Ut,
                Eigen::MatrixXd& Vt) {
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(U);
  const Eigen::Index k = std::min(U.rows(), U.cols());
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(U.rows(), k);
  const Eigen::MatrixXd R = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>();
  truncate(Q, V * R.transpose(), tolerance, Ut, Vt);
}

/// [A B] side by side (B's rows of A's count).
Eigen::MatrixXd beside(const Eigen::MatrixXd& A, const Eigen::Ref<const Eigen::MatrixXd>& B) {
  Eigen::MatrixXd out(A.rows(), A.cols() + B.cols());
  out << A, B;
  return out;
}

/// The pass over `node`; `block`: its largest subtrees of at most block.rows rows (a leaf at
/// least) are each passed over block.sweeps times, `inside` one of them.
void gauss_seidel(const HodlrMatrix::Node& node, int g, const std::function<void(Eigen::Index)>& visit,
                  const Eigen::VectorXd& x, Eigen::VectorXd& y, const SweepBlocks& block, bool inside = false) {
  const Eigen::Index n = node.end - node.begin;
  if (!inside && block.sweeps > 1 && (node.leaf() || n <= block.rows)) {
    for (int k = 0; k < block.sweeps; ++k) gauss_seidel(node, g, visit, x, y, block, true);
    return;
  }
  if (node.leaf()) {
    Eigen::VectorXd old(g), change(g);  // one allocation per leaf, not per granule
    for (Eigen::Index first = node.begin; first < node.end; first += g) {
      old = x.segment(first, g);
      visit(first);
      change = x.segment(first, g) - old;
      y.segment(node.begin, n).noalias() += node.dense.middleCols(first - node.begin, g) * change;
    }
    return;
  }
  const HodlrMatrix::Node &a = *node.first, &b = *node.second;
  const Eigen::Index n1 = a.end - a.begin, n2 = b.end - b.begin;
  Eigen::VectorXd dx1 = -x.segment(a.begin, n1);
  gauss_seidel(a, g, visit, x, y, block, inside);
  dx1 += x.segment(a.begin, n1);
  add_block_product<Eigen::VectorXd>(node.U21, node.V21, dx1, y.segment(b.begin, n2));
  Eigen::VectorXd dx2 = -x.segment(b.begin, n2);
  gauss_seidel(b, g, visit, x, y, block, inside);
  dx2 += x.segment(b.begin, n2);
  add_block_product<Eigen::VectorXd>(node.U12(), node.V12(), dx2, y.segment(a.begin, n1));
}

/// Rows [begin, begin + M.rows()) of blockdiag(C) M, C's blocks g x g side by side.
Eigen::MatrixXd left_blocks(const Eigen::MatrixXd& C, Eigen::Index begin, const Eigen::MatrixXd& M, int g) {
  Eigen::MatrixXd out(M.rows(), M.cols());
  for (Eigen::Index r = 0; r < M.rows(); r += g) out.middleRows(r, g) = C.middleCols(begin + r, g) * M.middleRows(r, g);
  return out;
}

std::unique_ptr<HodlrMatrix::Node> mixed(const HodlrMatrix::Node& a, const Eigen::MatrixXd& Cw,
                                         const Eigen::MatrixXd& Cy, int g) {
  auto node = std::make_unique<HodlrMatrix::Node>();
  node->begin = a.begin, node->end = a.end;
  if (a.leaf()) {
    node->dense = left_blocks(Cw, a.begin, a.dense, g);
    for (Eigen::Index r = 0; r < a.dense.rows(); r += g) node->dense.block(r, r, g, g) += Cy.middleCols(a.begin + r, g);
    return node;
  }
  node->first = mixed(*a.first, Cw, Cy, g);
  node->second = mixed(*a.second, Cw, Cy, g);
  node->U12_own = left_blocks(Cw, a.first->begin, a.U12(), g), node->V12_own = a.V12();
  node->U21 = left_blocks(Cw, a.second->begin, a.U21, g), node->V21 = a.V21;
  return node;
}

/// node = C_y + C_w a again on the granule at row `first` (node mixed from a before).
void remix(HodlrMatrix::Node& node, const HodlrMatrix::Node& a, const Eigen::MatrixXd& Cw, const Eigen::MatrixXd& Cy,
           Eigen::Index first, int g) {
  const auto C = Cw.middleCols(first, g);
  if (a.leaf()) {
    const Eigen::Index r = first - a.begin;
    node.dense.middleRows(r, g).noalias() = C * a.dense.middleRows(r, g);
    node.dense.block(r, r, g, g) += Cy.middleCols(first, g);
    return;
  }
  if (first < a.second->begin) {
    node.U12_own.middleRows(first - a.begin, g).noalias() = C * a.U12().middleRows(first - a.begin, g);
    remix(*node.first, *a.first, Cw, Cy, first, g);
  } else {
    node.U21.middleRows(first - a.second->begin, g).noalias() = C * a.U21.middleRows(first - a.second->begin, g);
    remix(*node.second, *a.second, Cw, Cy, first, g);
  }
}

template <class Node, class F>
void visit(Node& node, F&& f) {
  f(node);
  if (node.leaf()) return;
  visit(*node.first, f);
  visit(*node.second, f);
}

}  // namespace

HodlrMatrix::HodlrMatrix(const Eigen::MatrixXd& A, double tolerance, int leaf_size, int granule)
    : size_(A.rows()), granule_(granule) {
  std::mt19937 rng(20261125);
  root_ = bisections(0, size_, std::max(leaf_size, 2 * granule), granule);
  visit(*root_, [&](Node& n) {
    if (n.leaf()) {
      n.dense = A.block(n.begin, n.begin, n.end - n.begin, n.end - n.begin);
      return;
    }
    const Eigen::Index mid = n.second->begin, n1 = mid - n.begin, n2 = n.end - mid;
    compress(A.block(n.begin, mid, n1, n2), tolerance, rng, n.U12_own, n.V12_own);
    compress(A.block(mid, n.begin, n2, n1), tolerance, rng, n.U21, n.V21);
  });
}

// Peeling (Lin, Lu and Ying, J. Comput. Phys. 230, 2011), level by level from the root: the
// probes of one level are random on the second half of each of its bisections and zero
// elsewhere, so that on the first halves A omega is the off-diagonal blocks' products plus
// what the coarser levels' blocks contribute, which are known and subtracted. One block of
// products per round serves all the level's bisections.
HodlrMatrix HodlrMatrix::symmetric(Eigen::Index size, const Products& A, double relative_tolerance, int leaf_size,
                                   int granule) {
  HodlrMatrix H;
  H.size_ = size, H.granule_ = granule;
  H.root_ = bisections(0, size, std::max(leaf_size, 2 * granule), granule);
  std::vector<Node*> leaves;
  collect(*H.root_, 0, true, leaves);
  // The leaves' unit probes, all leaves at once (column c: each leaf's c-th row): their
  // products scale the tolerance by the diagonal, and give the leaves once the blocks are known.
  Eigen::Index width = 0;
  for (const Node* leaf : leaves) width = std::max(width, leaf->end - leaf->begin);
  Eigen::MatrixXd units = Eigen::MatrixXd::Zero(size, width);
  for (const Node* leaf : leaves)
    for (Eigen::Index c = 0; c < leaf->end - leaf->begin; ++c) units(leaf->begin + c, c) = 1.0;
  Eigen::MatrixXd leaf_products = A(units);
  double scale = 0;
  for (const Node* leaf : leaves)
    for (Eigen::Index c = 0; c < leaf->end - leaf->begin; ++c)
      scale = std::max(scale, std::abs(leaf_products(leaf->begin + c, c)));
  const double tolerance = relative_tolerance * scale;

  std::mt19937 rng(20261125);
  std::vector<Node*> level;
  Eigen::Index coarser_rank = 0;  // the largest basis of the level above
  for (int depth = 0; level.clear(), collect(*H.root_, depth, false, level), !level.empty(); ++depth) {
    std::vector<RangeFinder> ranges;
    for (const Node* n : level) {
      const Eigen::Index n1 = n->first->end - n->begin, n2 = n->end - n->second->begin;
      ranges.emplace_back(n1, std::min(n1, n2));
    }
    const auto products = [&](const Eigen::MatrixXd& X) {
      Eigen::MatrixXd Y = A(X);
      subtract_coarse(*H.root_, depth, X, Y);
      return Y;
    };
    // The first round as wide as half the level above's basis (the blocks' ranks fall by less
    // than that from level to level: no probe is wasted), the rest by rounds of `probes`: a wide
    // block of products costs far less per column (a sparse solve streams the body's factor
    // once per block, whatever its width up to the BLAS's).
    Eigen::Index width = std::max<Eigen::Index>(probes, coarser_rank / 2 / probes * probes);
    for (bool open = true; open; width = probes) {  // the blocks A(first, second) by their ranges
      Eigen::MatrixXd omega = Eigen::MatrixXd::Zero(size, width);
      for (std::size_t k = 0; k < level.size(); ++k)
        if (!ranges[k].done) gaussian(omega.middleRows(level[k]->second->begin, level[k]->end - level[k]->second->begin), rng);
      Eigen::MatrixXd Y = products(omega);
      open = false;
      for (std::size_t k = 0; k < level.size(); ++k) {
        if (ranges[k].done) continue;
        const Node& n = *level[k];
        ranges[k].take(Y.middleRows(n.begin, n.first->end - n.begin), tolerance, true);
        open = open || !ranges[k].done;
      }
    }
    // A(second, first) Q = B^T Q (A symmetric), B ~ Q (B^T Q)^T = U V^T truncated; and
    // A(second, first) = B^T = V U^T, mirrored into A(first, second).
    Eigen::Index rank = 0;
    for (const RangeFinder& r : ranges) rank = std::max(rank, r.Q.cols());
    coarser_rank = rank;
    Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(size, rank);
    for (std::size_t k = 0; k < level.size(); ++k)
      Q.block(level[k]->begin, 0, ranges[k].Q.rows(), ranges[k].Q.cols()) = ranges[k].Q;
    const Eigen::MatrixXd BtQ = rank > 0 ? products(Q) : Q;
    for (std::size_t k = 0; k < level.size(); ++k) {
      Node& n = *level[k];
      const Eigen::Index n2 = n.end - n.second->begin;
      truncate(ranges[k].Q, BtQ.block(n.second->begin, 0, n2, ranges[k].Q.cols()), tolerance, n.V21, n.U21);
      n.mirrored = true;
    }
  }
  subtract_coarse(*H.root_, std::numeric_limits<int>::max(), units, leaf_products);
  for (Node* leaf : leaves) leaf->dense = leaf_products.block(leaf->begin, 0, leaf->end - leaf->begin, leaf->end - leaf->begin);
  return H;
}

Eigen::MatrixXd HodlrMatrix::diagonal_block(Eigen::Index first, Eigen::Index n) const {
  const Node* node = root_.get();
  while (!node->leaf()) node = first < node->second->begin ? node->first.get() : node->second.get();
  RCCM_VERIFY(first + n <= node->end, "diagonal_block(): the block straddles two leaves");
  return node->dense.block(first - node->begin, first - node->begin, n, n);
}

double HodlrMatrix::diagonal_scale() const {
  double s = 0;
  visit(*root_, [&](const Node& n) {
    if (n.leaf()) s = std::max(s, n.dense.diagonal().cwiseAbs().maxCoeff());
  });
  return s;
}

HodlrMatrix::~HodlrMatrix() = default;
HodlrMatrix::HodlrMatrix(HodlrMatrix&&) noexcept = default;
HodlrMatrix& HodlrMatrix::operator=(HodlrMatrix&&) noexcept = default;

Eigen::VectorXd HodlrMatrix::multiply(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return rccm::multiply<Eigen::VectorXd>(*root_, x);
}

Eigen::MatrixXd HodlrMatrix::multiply_block(const Eigen::Ref<const Eigen::MatrixXd>& X) const {
  return rccm::multiply<Eigen::MatrixXd>(*root_, X);
}

void HodlrMatrix::gauss_seidel(const std::function<void(Eigen::Index)>& visit, const Eigen::VectorXd& x,
                               Eigen::VectorXd& y, const SweepBlocks& blocks) const {
  rccm::gauss_seidel(*root_, granule_, visit, x, y, blocks);
}

HodlrMatrix HodlrMatrix::rows_mixed(const Eigen::MatrixXd& Cw, const Eigen::MatrixXd& Cy) const {
  HodlrMatrix out;
  out.size_ = size_, out.granule_ = granule_;
  out.root_ = mixed(*root_, Cw, Cy, granule_);
  return out;
}

void HodlrMatrix::remix_rows(const HodlrMatrix& A, const Eigen::MatrixXd& Cw, const Eigen::MatrixXd& Cy,
                             const std::vector<Eigen::Index>& granules) {
  for (Eigen::Index first : granules) {
    RCCM_VERIFY(first % granule_ == 0 && first < size_, "remix_rows(): not the first row of a granule");
    rccm::remix(*root_, *A.root_, Cw, Cy, first, granule_);
  }
}

HodlrMatrix HodlrMatrix::truncated(double relative_tolerance) const {
  return plus(Eigen::MatrixXd(size_, 0), Eigen::MatrixXd(size_, 0), relative_tolerance);
}

HodlrMatrix HodlrMatrix::plus(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y, double relative_tolerance) const {
  RCCM_VERIFY(X.rows() == size_ && Y.rows() == size_ && X.cols() == Y.cols(), "plus(): X Y^T of another shape");
  const double tolerance = relative_tolerance * diagonal_scale();
  const std::function<std::unique_ptr<Node>(const Node&)> copy = [&](const Node& a) {
    auto n = std::make_unique<Node>();
    n->begin = a.begin, n->end = a.end;
    if (a.leaf()) {
      const Eigen::Index rows = a.end - a.begin;
      n->dense = a.dense;
      if (X.cols() > 0) n->dense.noalias() += X.middleRows(a.begin, rows) * Y.middleRows(a.begin, rows).transpose();
      return n;
    }
    n->first = copy(*a.first);
    n->second = copy(*a.second);
    const Eigen::Index b1 = a.first->begin, n1 = a.first->end - b1, b2 = a.second->begin, n2 = a.end - b2;
    n->mirrored = a.mirrored;
    if (!a.mirrored)
      recompress(beside(a.U12(), X.middleRows(b1, n1)), beside(a.V12(), Y.middleRows(b2, n2)), tolerance, n->U12_own, n->V12_own);
    recompress(beside(a.U21, X.middleRows(b2, n2)), beside(a.V21, Y.middleRows(b1, n1)), tolerance, n->U21, n->V21);
    return n;
  };
  HodlrMatrix out;
  out.size_ = size_, out.granule_ = granule_;
  out.root_ = copy(*root_);
  return out;
}

int HodlrMatrix::max_rank() const {
  Eigen::Index r = 0;
  visit(*root_, [&](const Node& n) { r = std::max({r, n.U12().cols(), n.U21.cols()}); });
  return static_cast<int>(r);
}

Eigen::Index HodlrMatrix::stored() const {
  Eigen::Index s = 0;
  visit(*root_, [&](const Node& n) { s += n.dense.size() + n.U12_own.size() + n.V12_own.size() + n.U21.size() + n.V21.size(); });
  return s;
}

// A = diag(A11, A22) + U Vt with U = [U12 0; 0 U21], Vt = [0 V12^T; V21^T 0]. With
// X = diag(A11, A22)^-1 U, A^-1 b = z - X (I + Vt X)^-1 Vt z, z = diag(A11, A22)^-1 b.
struct HodlrSolver::Node {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;  // a leaf
  std::unique_ptr<Node> first, second;
  Eigen::Index n1 = 0;
  Eigen::MatrixXd X1, X2;                   // A11^-1 U12, A22^-1 U21
  Eigen::MatrixXd V12, V21;
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance;  // I + Vt X

  Eigen::MatrixXd solve(const Eigen::Ref<const Eigen::MatrixXd>& B) const {
    // No columns (a rank-zero block's factor): Eigen's triangular solve would bind a reference
    // to the empty matrix's first coefficient (undefined behaviour, found by UBSan).
    if (B.cols() == 0) return Eigen::MatrixXd(B.rows(), 0);
    if (!first) return lu.solve(B);
    const Eigen::Index n2 = B.rows() - n1, r1 = X1.cols();
    Eigen::MatrixXd z(B.rows(), B.cols());
    z.topRows(n1) = first->solve(B.topRows(n1));
    z.bottomRows(n2) = second->solve(B.bottomRows(n2));
    if (r1 + X2.cols() == 0) return z;  // the halves do not couple
    Eigen::MatrixXd t(r1 + X2.cols(), B.cols());
    t.topRows(r1) = V12.transpose() * z.bottomRows(n2);
    t.bottomRows(X2.cols()) = V21.transpose() * z.topRows(n1);
    const Eigen::MatrixXd w = capacitance.solve(t);
    z.topRows(n1) -= X1 * w.topRows(r1);
    z.bottomRows(n2) -= X2 * w.bottomRows(X2.cols());
    return z;
  }
};

namespace {

/// The solver's tree, the matrix's shape and right factors V (rows do not change them: a
/// refactorization keeps them), nothing factorized yet.
std::unique_ptr<HodlrSolver::Node> shape(const HodlrMatrix::Node& a) {
  auto node = std::make_unique<HodlrSolver::Node>();
  if (a.leaf()) return node;
  node->n1 = a.first->end - a.first->begin;
  node->V12 = a.V12(), node->V21 = a.V21;
  node->first = shape(*a.first);
  node->second = shape(*a.second);
  return node;
}

/// Factorizes the nodes whose rows [begin, end) are touched(begin, end), keeping the others'.
template <class Touched>
void factorize(HodlrSolver::Node& node, const HodlrMatrix::Node& a, const Touched& touched) {
  if (!touched(a.begin, a.end)) return;
  if (a.leaf()) {
    node.lu.compute(a.dense);
    return;
  }
  factorize(*node.first, *a.first, touched);
  factorize(*node.second, *a.second, touched);
  if (touched(a.first->begin, a.first->end)) node.X1 = node.first->solve(a.U12());
  if (touched(a.second->begin, a.second->end)) node.X2 = node.second->solve(a.U21);
  const Eigen::Index r1 = a.U12().cols(), r2 = a.U21.cols();
  if (r1 + r2 == 0) return;
  Eigen::MatrixXd K = Eigen::MatrixXd::Identity(r1 + r2, r1 + r2);
  K.topRightCorner(r1, r2) = a.V12().transpose() * node.X2;
  K.bottomLeftCorner(r2, r1) = a.V21.transpose() * node.X1;
  node.capacitance.compute(K);
}

}  // namespace

HodlrSolver::HodlrSolver(const HodlrMatrix& A) : root_(shape(*A.root_)) {
  factorize(*root_, *A.root_, [](Eigen::Index, Eigen::Index) { return true; });
}

void HodlrSolver::refactorize(const HodlrMatrix& A, const std::vector<Eigen::Index>& rows) {
  RCCM_VERIFY(std::is_sorted(rows.begin(), rows.end()), "refactorize(): the changed rows must be sorted");
  factorize(*root_, *A.root_, [&](Eigen::Index begin, Eigen::Index end) {
    const auto it = std::lower_bound(rows.begin(), rows.end(), begin);
    return it != rows.end() && *it < end;
  });
}

HodlrSolver::~HodlrSolver() = default;
HodlrSolver::HodlrSolver(HodlrSolver&&) noexcept = default;
HodlrSolver& HodlrSolver::operator=(HodlrSolver&&) noexcept = default;

Eigen::MatrixXd HodlrSolver::solve(const Eigen::MatrixXd& B) const { return root_->solve(B); }

}  // namespace rccm
