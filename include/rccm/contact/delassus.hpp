// The flexibility (Delassus) operator W0 of the condensed interface problem
// (docs/MODEL.md s4): u = W0 y + q0, with W0 = P K0^-1 P^T. The contact solvers see it only
// through this interface, so that a sparse or matrix-free operator can replace the dense one.
#pragma once

#include "rccm/interface/layout.hpp"
#include "rccm/la/hodlr.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <functional>
#include <optional>
#include <string>

namespace rccm {

class DelassusOperator {
 public:
  virtual ~DelassusOperator() = default;

  /// Rows and columns: the stacked local components of the contact pairs.
  virtual Eigen::Index size() const = 0;

  /// u = W0 y (u may be a column of a matrix).
  virtual void multiply(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> u) const = 0;

  /// u += W0 (:, first .. first + dy.size() - 1) dy: the response to a change of one pair's force.
  virtual void add_response(Eigen::Index first, const LocalVector& dy, Eigen::VectorXd& u) const = 0;

  /// A Gauss-Seidel pass over the pairs (of `dim` rows each), in order: update(i) changes pair
  /// i's entries of y, reading its entries of u, which keep up with y's earlier changes
  /// (u - W0 y is what it was at the pass's start, on that pair on entry to update(i) and
  /// everywhere after the pass). By `blocks` (la/hodlr.hpp: each block of neighbouring pairs
  /// updated blocks.sweeps times before the next; consecutive pairs here, the hierarchy's
  /// subtrees where W0 is compressed). Pair by pair with add_response unless overridden. If
  /// update throws, u is left behind y: the caller discards both.
  virtual void gauss_seidel(int dim, const std::function<void(int)>& update, Eigen::VectorXd& y, Eigen::VectorXd& u,
                            const SweepBlocks& blocks) const;

  /// The diagonal block W0 (first.., first..) of one pair, of size n.
  virtual LocalMatrix block(Eigen::Index first, int n) const = 0;

  /// The largest magnitude on the diagonal (a scale for "no flexibility").
  virtual double diagonal_scale() const = 0;

  /// How W0 is stored and its memory, for the run report: "dense, 198 x 198 (0.3 MB)"; a
  /// compressed W0 also names the threads of its large blocks' products (la/hodlr.cpp).
  virtual std::string storage() const = 0;

  /// The matrix itself when it is stored dense (the exact active-set step and the plain form
  /// need it); nullptr otherwise.
  virtual const Eigen::MatrixXd* dense() const { return nullptr; }

  /// W0 compressed (la/hodlr.hpp) when it is kept so: products and sweeps use it.
  virtual const HodlrMatrix* compressed() const { return nullptr; }
  /// The compression the exact step mixes and factorizes its matrix from: compressed()
  /// truncated to lower ranks, its error left to the refinement's products with compressed().
  virtual const HodlrMatrix* compressed_preconditioner() const { return nullptr; }
};

/// A Gauss-Seidel pass over the pairs of `dim` rows of y in rows [begin, end), in order:
/// update(i) changes pair i's entries, then respond(first, dy) answers their change dy (a Vec;
/// a pair left as it was, separated at 0, moves nothing).
template <class Vec, class Update, class Respond>
void pass_over_pairs(int dim, const Update& update, const Respond& respond, Eigen::VectorXd& y, Eigen::Index begin,
                     Eigen::Index end) {
  for (Eigen::Index first = begin; first < end; first += dim) {
    const Vec old = y.segment(first, dim);
    update(static_cast<int>(first / dim));
    const Vec dy = y.segment(first, dim) - old;
    if (!dy.isZero(0.0)) respond(first, dy);
  }
}

/// u += W (:, first .. first + dim - 1) dy on a dense W, on the n rows from `begin`: the sweeps'
/// inner loop (half a 3D run's time), the pair's 2-3 columns in one pass over u.
template <int dim>
void add_columns(const Eigen::MatrixXd& W, Eigen::Index first, const Eigen::Matrix<double, dim, 1>& dy,
                 Eigen::VectorXd& u, Eigen::Index begin, Eigen::Index n) {
  const Eigen::Index m = W.rows();
  const double* w = W.data() + first * m + begin;
  double* x = u.data() + begin;
  if constexpr (dim == 2) {
    const double a = dy[0], b = dy[1];
    for (Eigen::Index i = 0; i < n; ++i) x[i] += w[i] * a + w[m + i] * b;
  } else {
    const double a = dy[0], b = dy[1], c = dy[2];
    for (Eigen::Index i = 0; i < n; ++i) x[i] += w[i] * a + w[m + i] * b + w[2 * m + i] * c;
  }
}

/// The rows of `blocks`' blocks over m rows of pairs of `dim` rows: whole pairs, one at least;
/// all m rows where each block is swept once (the plain pass).
inline Eigen::Index block_rows(const SweepBlocks& blocks, int dim, Eigen::Index m) {
  return blocks.sweeps > 1 ? std::max<Eigen::Index>(dim, blocks.rows / dim * dim) : m;
}

/// W0.gauss_seidel(dim, update, y, u, blocks), with `update` and the pairs' responses inlined
/// where W0 is dense (through std::function and run-time sized pairs, the pass cost a cold
/// solve of a few pairs more than its local solves). A block answers its pairs' changes on its
/// own rows during its sweeps, and on the others' once after them (the plain pass: one block
/// of all rows, nothing after).
template <int dim, class Update>
void gauss_seidel_pass(const DelassusOperator& W0, const Update& update, Eigen::VectorXd& y, Eigen::VectorXd& u,
                       const SweepBlocks& blocks) {
  const Eigen::MatrixXd* W = W0.dense();
  if (W == nullptr) return W0.gauss_seidel(dim, update, y, u, blocks);
  using Vec = Eigen::Matrix<double, dim, 1>;
  const Eigen::Index m = y.size(), rows = block_rows(blocks, dim, m);
  Eigen::VectorXd dY(rows < m ? rows : 0);  // a block's change, for the rows outside it
  for (Eigen::Index begin = 0; begin < m; begin += rows) {
    const Eigen::Index n = std::min(rows, m - begin), after = begin + n;
    if (n < m) dY.head(n) = -y.segment(begin, n);
    for (int k = 0; k < std::max(blocks.sweeps, 1); ++k)
      pass_over_pairs<Vec>(dim, update, [&](Eigen::Index first, const Vec& dy) { add_columns<dim>(*W, first, dy, u, begin, n); },
                           y, begin, after);
    if (n == m) continue;
    dY.head(n) += y.segment(begin, n);
    u.head(begin).noalias() += W->block(0, begin, begin, n) * dY.head(n);
    u.tail(m - after).noalias() += W->block(after, begin, m - after, n) * dY.head(n);
  }
}

/// W0 stored as a dense symmetric matrix (m^2 memory): the default below a few hundred pairs.
class DenseDelassus final : public DelassusOperator {
 public:
  explicit DenseDelassus(Eigen::MatrixXd W);
  Eigen::Index size() const override { return W_.rows(); }
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> u) const override;
  void add_response(Eigen::Index first, const LocalVector& dy, Eigen::VectorXd& u) const override;
  LocalMatrix block(Eigen::Index first, int n) const override { return W_.block(first, first, n, n); }
  double diagonal_scale() const override { return diagonal_scale_; }
  std::string storage() const override;
  const Eigen::MatrixXd* dense() const override { return &W_; }

 private:
  Eigen::MatrixXd W_;
  double diagonal_scale_;
};

/// W0 known only compressed (la/hodlr.hpp), never formed: memory, products and Gauss-Seidel
/// passes about m r log m instead of m^2 (the off-diagonal blocks' rank r is 15-20 on an
/// interface line), to an accuracy of tuning::hodlr_accuracy relative to its diagonal. The
/// large-interface default (solver.compressed_min_nodes); the pairs' blocks are the leaves'.
class CompressedDelassus final : public DelassusOperator {
 public:
  explicit CompressedDelassus(HodlrMatrix W);
  Eigen::Index size() const override { return W_.size(); }
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> u) const override;
  /// By a product (m r log m): the sweeps go through gauss_seidel instead.
  void add_response(Eigen::Index first, const LocalVector& dy, Eigen::VectorXd& u) const override;
  /// By the hierarchy: the leaves' columns, then each bisection's blocks once (and a block's
  /// subtree again for each of its further sweeps).
  void gauss_seidel(int dim, const std::function<void(int)>& update, Eigen::VectorXd& y, Eigen::VectorXd& u,
                    const SweepBlocks& blocks) const override;
  LocalMatrix block(Eigen::Index first, int n) const override { return W_.diagonal_block(first, n); }
  double diagonal_scale() const override { return diagonal_scale_; }
  /// With the share of the dense matrix it stores and the largest rank of its blocks.
  std::string storage() const override;
  const HodlrMatrix* compressed() const override { return &W_; }
  /// Truncated at the first call: only the exact step asks (never the 3D sweeps), and a W0
  /// replaced when the springs follow beta is truncated again only if asked.
  const HodlrMatrix* compressed_preconditioner() const override;

 private:
  HodlrMatrix W_;
  mutable std::optional<HodlrMatrix> preconditioner_;  // W_ truncated to tuning::hodlr_preconditioner_accuracy
  double diagonal_scale_;
};

/// W0 stored as a sparse matrix (memory and products proportional to its nonzeros): the
/// Delassus operator of a multibody problem, whose contacts each couple a few bodies
/// (Siconos' granular flows). Only the Gauss-Seidel sweeps can use it: the exact active-set
/// step, rccm and newton need the dense W0.
class SparseDelassus final : public DelassusOperator {
 public:
  explicit SparseDelassus(Eigen::SparseMatrix<double> W);
  Eigen::Index size() const override { return W_.rows(); }
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> u) const override;
  void add_response(Eigen::Index first, const LocalVector& dy, Eigen::VectorXd& u) const override;
  LocalMatrix block(Eigen::Index first, int n) const override;
  double diagonal_scale() const override { return diagonal_scale_; }
  std::string storage() const override;
  const Eigen::SparseMatrix<double>& matrix() const { return W_; }

 private:
  Eigen::SparseMatrix<double> W_;  // compressed columns: add_response reads columns
  double diagonal_scale_;
};

}  // namespace rccm
