#include "rccm/la/hodlr.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <random>

namespace rccm {

struct HodlrMatrix::Node {
  Eigen::Index begin = 0, end = 0;
  Eigen::MatrixXd dense;                  // a leaf's block
  std::unique_ptr<Node> first, second;    // the halves of a bisection
  Eigen::MatrixXd U12, V12, U21, V21;     // A(first, second) = U12 V12^T, A(second, first) = U21 V21^T
  bool leaf() const { return !first; }
};

namespace {

/// B ~ U V^T with |B - U V^T|_F <= tolerance (with high probability): an orthonormal basis
/// of B's range grown by blocks of random probes until the probes' residual is below the
/// tolerance (Halko, Martinsson and Tropp, SIAM Rev. 53, 2011, alg. 4.2), then truncated by
/// the SVD of the small factor.
void compress(const Eigen::Ref<const Eigen::MatrixXd>& B, double tolerance, std::mt19937& rng, Eigen::MatrixXd& U,
              Eigen::MatrixXd& V) {
  constexpr int probes = 8;
  const Eigen::Index n1 = B.rows(), n2 = B.cols(), full = std::min(n1, n2);
  std::normal_distribution<double> gauss;
  Eigen::MatrixXd Q(n1, 0);
  double floor = 0;  // round-off of B's products: no basis is grown from it
  const auto orthogonalize = [&Q](Eigen::MatrixXd& Y) {
    for (int pass = 0; pass < 2; ++pass) Y -= Q * (Q.transpose() * Y);  // twice: orthogonal to round-off
  };
  while (Q.cols() < full) {
    Eigen::MatrixXd omega(n2, probes);
    for (Eigen::Index k = 0; k < omega.size(); ++k) omega.data()[k] = gauss(rng);
    Eigen::MatrixXd Y = B * omega;
    if (Q.cols() == 0) floor = 1e-14 * Y.colwise().norm().maxCoeff();
    orthogonalize(Y);
    // E |M w|^2 = |M|_F^2 for a Gaussian w; the largest of `probes` samples, with a margin of 10.
    if (10.0 * Y.colwise().norm().maxCoeff() <= std::max(tolerance, floor)) break;
    const Eigen::Index add = std::min<Eigen::Index>(probes, full - Q.cols());
    Eigen::MatrixXd basis = Eigen::HouseholderQR<Eigen::MatrixXd>(Y).householderQ() * Eigen::MatrixXd::Identity(n1, add);
    orthogonalize(basis);  // Y's round-off is not orthogonal to Q
    basis = Eigen::HouseholderQR<Eigen::MatrixXd>(basis).householderQ() * Eigen::MatrixXd::Identity(n1, add);
    Q.conservativeResize(n1, Q.cols() + add);
    Q.rightCols(add) = basis;
  }
  if (Q.cols() == 0) {  // B below the tolerance: rank zero
    U.resize(n1, 0), V.resize(n2, 0);
    return;
  }
  const Eigen::MatrixXd Vq = B.transpose() * Q;  // B ~ Q Vq^T
  // Jacobi, not BDCSVD: Eigen 3.4's BDCSVD lost 1e-6 of |B| on W0's blocks (singular values
  // falling to 1e-9 of the largest). Vq has Q's columns, few on low-rank blocks (on a block
  // of full rank Jacobi is slower, and the compression pointless anyway).
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Vq, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  // Keep the singular values whose tail exceeds the tolerance.
  Eigen::Index rank = s.size();
  double tail = 0;
  while (rank > 0 && tail + s[rank - 1] * s[rank - 1] <= 0.25 * tolerance * tolerance)
    tail += s[rank - 1] * s[rank - 1], --rank;
  U = Q * svd.matrixV().leftCols(rank) * s.head(rank).asDiagonal();
  V = svd.matrixU().leftCols(rank);
}

std::unique_ptr<HodlrMatrix::Node> build(const Eigen::MatrixXd& A, Eigen::Index begin, Eigen::Index end,
                                         double tolerance, int leaf_size, int granule, std::mt19937& rng) {
  auto node = std::make_unique<HodlrMatrix::Node>();
  node->begin = begin, node->end = end;
  const Eigen::Index n = end - begin, mid = begin + (n / 2 / granule) * granule;
  if (n <= leaf_size || mid == begin) {
    node->dense = A.block(begin, begin, n, n);
    return node;
  }
  node->first = build(A, begin, mid, tolerance, leaf_size, granule, rng);
  node->second = build(A, mid, end, tolerance, leaf_size, granule, rng);
  compress(A.block(begin, mid, mid - begin, end - mid), tolerance, rng, node->U12, node->V12);
  compress(A.block(mid, begin, end - mid, mid - begin), tolerance, rng, node->U21, node->V21);
  return node;
}

Eigen::VectorXd multiply(const HodlrMatrix::Node& node, const Eigen::Ref<const Eigen::VectorXd>& x) {
  if (node.leaf()) return node.dense * x;
  const Eigen::Index n1 = node.first->end - node.first->begin, n2 = node.end - node.begin - n1;
  Eigen::VectorXd y(x.size());
  y.head(n1) = multiply(*node.first, x.head(n1)) + node.U12 * (node.V12.transpose() * x.tail(n2));
  y.tail(n2) = multiply(*node.second, x.tail(n2)) + node.U21 * (node.V21.transpose() * x.head(n1));
  return y;
}

void gauss_seidel(const HodlrMatrix::Node& node, int g, const std::function<void(Eigen::Index)>& visit,
                  const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  const Eigen::Index n = node.end - node.begin;
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
  const Eigen::VectorXd x1 = x.segment(a.begin, a.end - a.begin);
  gauss_seidel(a, g, visit, x, y);
  y.segment(b.begin, b.end - b.begin) += node.U21 * (node.V21.transpose() * (x.segment(a.begin, a.end - a.begin) - x1));
  const Eigen::VectorXd x2 = x.segment(b.begin, b.end - b.begin);
  gauss_seidel(b, g, visit, x, y);
  y.segment(a.begin, a.end - a.begin) += node.U12 * (node.V12.transpose() * (x.segment(b.begin, b.end - b.begin) - x2));
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
  node->U12 = left_blocks(Cw, a.first->begin, a.U12, g), node->V12 = a.V12;
  node->U21 = left_blocks(Cw, a.second->begin, a.U21, g), node->V21 = a.V21;
  return node;
}

template <class F>
void visit(const HodlrMatrix::Node& node, F&& f) {
  f(node);
  if (node.leaf()) return;
  visit(*node.first, f);
  visit(*node.second, f);
}

}  // namespace

HodlrMatrix::HodlrMatrix(const Eigen::MatrixXd& A, double tolerance, int leaf_size, int granule)
    : size_(A.rows()), granule_(granule) {
  std::mt19937 rng(20261125);
  root_ = build(A, 0, size_, tolerance, std::max(leaf_size, 2 * granule), granule, rng);
}

HodlrMatrix::~HodlrMatrix() = default;
HodlrMatrix::HodlrMatrix(HodlrMatrix&&) noexcept = default;
HodlrMatrix& HodlrMatrix::operator=(HodlrMatrix&&) noexcept = default;

Eigen::VectorXd HodlrMatrix::multiply(const Eigen::Ref<const Eigen::VectorXd>& x) const { return rccm::multiply(*root_, x); }

void HodlrMatrix::gauss_seidel(const std::function<void(Eigen::Index)>& visit, const Eigen::VectorXd& x,
                               Eigen::VectorXd& y) const {
  rccm::gauss_seidel(*root_, granule_, visit, x, y);
}

HodlrMatrix HodlrMatrix::rows_mixed(const Eigen::MatrixXd& Cw, const Eigen::MatrixXd& Cy) const {
  HodlrMatrix out;
  out.size_ = size_, out.granule_ = granule_;
  out.root_ = mixed(*root_, Cw, Cy, granule_);
  return out;
}

int HodlrMatrix::max_rank() const {
  Eigen::Index r = 0;
  visit(*root_, [&](const Node& n) { r = std::max({r, n.U12.cols(), n.U21.cols()}); });
  return static_cast<int>(r);
}

Eigen::Index HodlrMatrix::stored() const {
  Eigen::Index s = 0;
  visit(*root_, [&](const Node& n) { s += n.dense.size() + n.U12.size() + n.V12.size() + n.U21.size() + n.V21.size(); });
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

std::unique_ptr<HodlrSolver::Node> factorize(const HodlrMatrix::Node& a) {
  auto node = std::make_unique<HodlrSolver::Node>();
  if (a.leaf()) {
    node->lu.compute(a.dense);
    return node;
  }
  node->first = factorize(*a.first);
  node->second = factorize(*a.second);
  node->n1 = a.first->end - a.first->begin;
  node->X1 = node->first->solve(a.U12);
  node->X2 = node->second->solve(a.U21);
  node->V12 = a.V12, node->V21 = a.V21;
  const Eigen::Index r1 = a.U12.cols(), r2 = a.U21.cols();
  if (r1 + r2 == 0) return node;
  Eigen::MatrixXd K = Eigen::MatrixXd::Identity(r1 + r2, r1 + r2);
  K.topRightCorner(r1, r2) = a.V12.transpose() * node->X2;
  K.bottomLeftCorner(r2, r1) = a.V21.transpose() * node->X1;
  node->capacitance.compute(K);
  return node;
}

}  // namespace

HodlrSolver::HodlrSolver(const HodlrMatrix& A) : root_(factorize(*A.root_)) {}
HodlrSolver::~HodlrSolver() = default;
HodlrSolver::HodlrSolver(HodlrSolver&&) noexcept = default;
HodlrSolver& HodlrSolver::operator=(HodlrSolver&&) noexcept = default;

Eigen::MatrixXd HodlrSolver::solve(const Eigen::MatrixXd& B) const { return root_->solve(B); }

}  // namespace rccm
