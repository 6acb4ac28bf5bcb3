#include "rccm/la/hodlr.hpp"

#include "rccm/la/blas_threads.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <omp.h>

#include <algorithm>
#include <cmath>

using namespace rccm;

namespace {

/// A smooth kernel on points of a line, plus a diagonal: the off-diagonal blocks have a
/// rapidly decaying spectrum, like the flexibility of an interface line.
Eigen::MatrixXd kernel_matrix(int m) {
  Eigen::MatrixXd A(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) A(i, j) = 1.0 / (1.0 + 20.0 * std::abs(i - j) / m);
  A.diagonal().array() += 2.0;
  return A;
}

/// Points of a side x side grid in row order (each bisection halves the rows: strips as wide
/// as the grid), a smooth kernel between them, plus a diagonal: as on an interface surface, the
/// blocks' ranks are high and fall slowly from level to level.
Eigen::MatrixXd surface_kernel(int side) {
  const int m = side * side;
  Eigen::MatrixXd A(m, m);
  const auto point = [&](int i) { return Eigen::Vector2d(i % side, i / side); };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) A(i, j) = 1.0 / (1.0 + (point(i) - point(j)).norm());
  A.diagonal().array() += 2.0;
  return A;
}

}  // namespace

TEST_CASE("HODLR: products and solves agree with the dense matrix to the compression tolerance", "[hodlr]") {
  const int m = 600;
  const Eigen::MatrixXd A = kernel_matrix(m);
  const double tolerance = 1e-12 * A.norm();
  const HodlrMatrix H(A, tolerance, 32, 2);
  REQUIRE(H.size() == m);
  // Compressed: the off-diagonal ranks stay far below the block sizes, the storage below m^2 / 3.
  CHECK(H.max_rank() <= 40);
  CHECK(H.stored() < m * m / 3);

  std::srand(3);
  const Eigen::VectorXd x = Eigen::VectorXd::Random(m);
  CHECK((H.multiply(x) - A * x).norm() <= 10 * tolerance * x.norm());

  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(m, 3);
  const Eigen::MatrixXd X = HodlrSolver(H).solve(B);
  const Eigen::MatrixXd X_dense = A.partialPivLu().solve(B);
  CHECK((X - X_dense).norm() <= 1e-9 * X_dense.norm());
  CHECK((A * X - B).norm() <= 1e-10 * B.norm());
}

TEST_CASE("HODLR: a symmetric matrix compressed from its products alone (peeling) is the matrix to the tolerance", "[hodlr]") {
  // The kernel is symmetric: by its products the same ranks as from its blocks, in a few
  // blocks of products per level, never m of them.
  const int m = 640;
  const Eigen::MatrixXd A = kernel_matrix(m);
  Eigen::Index columns = 0;
  const auto products = [&](const Eigen::MatrixXd& X) {
    columns += X.cols();
    return Eigen::MatrixXd(A * X);
  };
  const double relative = 1e-13, scale = A.diagonal().maxCoeff();
  const HodlrMatrix P = HodlrMatrix::symmetric(m, products, relative, 32, 2);
  const HodlrMatrix D(A, relative * scale, 32, 2);
  REQUIRE(P.size() == m);
  CHECK(P.granule() == 2);
  CHECK(P.max_rank() <= D.max_rank() + 2);
  CHECK(P.max_rank() >= D.max_rank() - 2);
  CHECK(columns < m / 2);
  // Each pair of blocks A(first, second) = A(second, first)^T stored once: beside the same
  // leaves (20 of 32 x 32), about half the compression of both blocks from A itself.
  const Eigen::Index leaves = 20 * 32 * 32;
  CHECK(P.stored() - leaves <= 0.55 * (D.stored() - leaves));
  CHECK(P.stored() - leaves >= 0.35 * (D.stored() - leaves));
  CHECK(P.diagonal_scale() == Approx(scale).epsilon(1e-13));
  for (Eigen::Index first : {0, 30, 320, 638})
    CHECK((P.diagonal_block(first, 2) - A.block(first, first, 2, 2)).norm() <= 10 * relative * scale);
  std::srand(4);
  for (int k = 0; k < 3; ++k) {
    const Eigen::VectorXd x = k == 0 ? Eigen::VectorXd(Eigen::VectorXd::Unit(m, 333)) : Eigen::VectorXd(Eigen::VectorXd::Random(m));
    CHECK((P.multiply(x) - A * x).norm() <= 100 * relative * scale * x.norm());
  }
  const Eigen::VectorXd b = Eigen::VectorXd::Random(m);
  CHECK((A * HodlrSolver(P).solve(b) - b).norm() <= 1e-10 * b.norm());
}

TEST_CASE("HODLR: peeled with zero rows and columns (a support holding contact nodes), still the matrix", "[hodlr]") {
  // W0's row and column of a component a support holds are zero: the blocks then have less
  // rank than rows, and a range finder that grew its basis from the round-off past that rank
  // lost the basis' orthogonality (a 3D interface with held nodes: W0 compressed 3.5 % off).
  for (int side : {8, 13}) {
    Eigen::MatrixXd A = surface_kernel(side);
    const int m = side * side;
    for (int i = 0; i < m; i += 7) A.row(i).setZero(), A.col(i).setZero();  // held components
    const auto products = [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(A * X); };
    for (int leaf : {12, 24, 48}) {
      const HodlrMatrix P = HodlrMatrix::symmetric(m, products, 1e-13, leaf, 1);
      const Eigen::MatrixXd dense = P.multiply_block(Eigen::MatrixXd::Identity(m, m));
      INFO(side << " x " << side << ", leaves of " << leaf << ": |P - A| / |A| = " << (dense - A).norm() / A.norm());
      CHECK((dense - A).norm() <= 1e-12 * A.norm());
      for (int i = 0; i < m; i += 7) CHECK(dense.row(i).norm() <= 1e-12 * A.norm());
    }
  }
}

TEST_CASE("HODLR: peeling a matrix with rank-one and uncoupled blocks", "[hodlr]") {
  // diag(d) + u v^T symmetric (u = v): every off-diagonal block has rank one; with the halves
  // uncoupled, rank zero; the coarser levels' blocks must be subtracted exactly for the finer
  // ones to stay at rank one.
  const int m = 256;
  std::srand(5);
  const Eigen::VectorXd u = Eigen::VectorXd::Random(m);
  Eigen::MatrixXd A = u * u.transpose();
  A.diagonal().array() += 3.0;
  const auto products = [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(A * X); };
  const HodlrMatrix H = HodlrMatrix::symmetric(m, products, 1e-13, 16, 1);
  CHECK(H.max_rank() == 1);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(m);
  CHECK((A * HodlrSolver(H).solve(b) - b).norm() <= 1e-12 * b.norm());
  A.topRightCorner(128, 128).setZero(), A.bottomLeftCorner(128, 128).setZero();
  const HodlrMatrix Z = HodlrMatrix::symmetric(m, products, 1e-13, 16, 1);
  CHECK(Z.max_rank() == 1);
  CHECK((Z.multiply(b) - A * b).norm() <= 1e-12 * (A * b).norm());
}

TEST_CASE("HODLR: exact on a matrix whose off-diagonal blocks have rank one", "[hodlr]") {
  // A = diag(d) + u v^T: every off-diagonal block has rank one.
  const int m = 256;
  std::srand(5);
  const Eigen::VectorXd u = Eigen::VectorXd::Random(m), v = Eigen::VectorXd::Random(m);
  Eigen::MatrixXd A = u * v.transpose();
  A.diagonal().array() += 3.0;
  const HodlrMatrix H(A, 1e-13 * A.norm(), 16, 1);
  CHECK(H.max_rank() == 1);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(m);
  const Eigen::VectorXd x = HodlrSolver(H).solve(b);
  CHECK((A * x - b).norm() <= 1e-12 * b.norm());
}

TEST_CASE("HODLR: rows mixed within pairs (the exact step's matrices) keep the ranks and solve", "[hodlr]") {
  // C_y + C_w W with block-diagonal 2 x 2 C's, as the exact step's rows are (nonsymmetric).
  const int m = 400;
  const Eigen::MatrixXd W = kernel_matrix(m);
  Eigen::MatrixXd Cw = Eigen::MatrixXd::Zero(m, m), Cy = Eigen::MatrixXd::Zero(m, m);
  for (int i = 0; i < m / 2; ++i) {
    const int f = 2 * i;
    Eigen::Matrix2d w, y = Eigen::Matrix2d::Zero();
    if (i % 3 == 0) {  // separated: Rbar = y - E u
      w << -0.5, 0.0, 0.0, -0.7;
      y.setIdentity();
    } else if (i % 3 == 1) {  // stick: u
      w.setIdentity();
    } else {  // slide: Rbar_t - s Rbar_n and u_n
      w << -0.3, 0.2 * 0.4, 0.0, 1.0;
      y << 1.0, -0.2, 0.0, 0.0;
    }
    Cw.block<2, 2>(f, f) = w, Cy.block<2, 2>(f, f) = y;
  }
  const Eigen::MatrixXd A = Cy + Cw * W;
  const HodlrMatrix Hw(W, 1e-12 * W.norm(), 32, 2), H(A, 1e-12 * A.norm(), 32, 2);
  CHECK(H.max_rank() <= Hw.max_rank() + 8);  // a left factor that is block diagonal adds no rank
  std::srand(9);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(m);
  const Eigen::VectorXd x = HodlrSolver(H).solve(b);
  CHECK((A * x - b).norm() <= 1e-9 * b.norm());
  // The same matrix from W's compression by mixing its rows: no recompression, same ranks.
  Eigen::MatrixXd Cw_blocks(2, m), Cy_blocks(2, m);
  for (int i = 0; i < m / 2; ++i)
    Cw_blocks.middleCols<2>(2 * i) = Cw.block<2, 2>(2 * i, 2 * i), Cy_blocks.middleCols<2>(2 * i) = Cy.block<2, 2>(2 * i, 2 * i);
  const HodlrMatrix Hm = Hw.rows_mixed(Cw_blocks, Cy_blocks);
  CHECK(Hm.max_rank() == Hw.max_rank());
  CHECK((Hm.multiply(b) - A * b).norm() <= 1e-10 * (A * b).norm());
  const Eigen::VectorXd xm = HodlrSolver(Hm).solve(b);
  CHECK((A * xm - b).norm() <= 1e-9 * b.norm());
}

TEST_CASE("HODLR: refactorized where rows changed, the factorization solves the new matrix, elsewhere it is kept", "[hodlr]") {
  // Pairs' rows mixed as the exact step's (stick: W's rows; separated: -E W + I), one pattern,
  // then another in which a few pairs (in two leaves) changed status.
  const int m = 512;
  const Eigen::MatrixXd W = kernel_matrix(m);
  const HodlrMatrix Hw(W, 1e-13 * W.diagonal().maxCoeff(), 32, 2);
  Eigen::MatrixXd Cw(2, m), Cy(2, m);
  const auto mixed = [&](const std::vector<int>& separated, Eigen::MatrixXd& dense) {
    Cy.setZero();
    for (int i = 0; i < m / 2; ++i) Cw.middleCols<2>(2 * i).setIdentity();
    for (int i : separated) Cw.middleCols<2>(2 * i) = -0.5 * Eigen::Matrix2d::Identity(), Cy.middleCols<2>(2 * i).setIdentity();
    dense = W;
    for (int i = 0; i < m / 2; ++i) {
      dense.middleRows<2>(2 * i) = Cw.middleCols<2>(2 * i) * W.middleRows<2>(2 * i);
      dense.block<2, 2>(2 * i, 2 * i) += Cy.middleCols<2>(2 * i);
    }
    return Hw.rows_mixed(Cw, Cy);
  };
  Eigen::MatrixXd A, B;
  const HodlrMatrix Ha = mixed({3, 4, 100}, A);
  const HodlrMatrix Hb = mixed({3, 4, 100, 101, 200}, B);  // pairs 101 and 200 changed: rows 202, 203, 400, 401
  std::srand(6);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(m);
  HodlrSolver S(Ha);
  REQUIRE((A * S.solve(b) - b).norm() <= 1e-9 * b.norm());
  S.refactorize(Hb, {});  // nothing changed by this account: the factorization of A stays
  CHECK((A * S.solve(b) - b).norm() <= 1e-9 * b.norm());
  CHECK((B * S.solve(b) - b).norm() > 1e-6 * b.norm());
  S.refactorize(Hb, {202, 203, 400, 401});
  CHECK((B * S.solve(b) - b).norm() <= 1e-9 * b.norm());
  CHECK((S.solve(b) - HodlrSolver(Hb).solve(b)).norm() <= 1e-12 * S.solve(b).norm());
  // The same matrix by mixing A's matrix again on the changed pairs' rows only.
  HodlrMatrix Hr = mixed({3, 4, 100}, A);
  mixed({3, 4, 100, 101, 200}, B);  // Cw, Cy of B
  Hr.remix_rows(Hw, Cw, Cy, {202, 400});
  for (const Eigen::VectorXd& x : {Eigen::VectorXd(b), Eigen::VectorXd(Eigen::VectorXd::Unit(m, 203)), Eigen::VectorXd(Eigen::VectorXd::Unit(m, 401))})
    CHECK((Hr.multiply(x) - Hb.multiply(x)).norm() <= 1e-14 * (B * x).norm());
}

TEST_CASE("HODLR: uncoupled halves have rank zero", "[hodlr]") {
  Eigen::MatrixXd A = kernel_matrix(128);
  A.topRightCorner(64, 64).setZero(), A.bottomLeftCorner(64, 64).setZero();
  const HodlrMatrix H(A, 1e-13 * A.norm(), 64, 1);
  CHECK(H.max_rank() == 0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(128, 1.0, 2.0);
  CHECK((A * HodlrSolver(H).solve(b) - b).norm() <= 1e-12 * b.norm());
}

TEST_CASE("HODLR: a singular diagonal block gives a solution that is not finite", "[hodlr]") {
  Eigen::MatrixXd A = kernel_matrix(128);
  A.row(5).setZero(), A.col(5).setZero();
  const HodlrMatrix H(A, 1e-13 * A.norm(), 16, 1);
  CHECK_FALSE(HodlrSolver(H).solve(Eigen::VectorXd::Ones(128)).allFinite());
}

TEST_CASE("HODLR: peeling a surface's kernel takes wide blocks of products where the ranks are high", "[hodlr]") {
  // A surface's kernel (surface_kernel): each level's first round of probes is half as wide as
  // the level above's basis, so the products come in far fewer blocks than rounds of 8 probes
  // would take (a block of products is a sparse solve of the whole body), without more columns
  // in all.
  const int m = 32 * 32;
  const Eigen::MatrixXd A = surface_kernel(32);
  Eigen::Index columns = 0, blocks = 0;
  const auto products = [&](const Eigen::MatrixXd& X) {
    columns += X.cols(), ++blocks;
    return Eigen::MatrixXd(A * X);
  };
  const double relative = 1e-10, scale = A.diagonal().maxCoeff();
  const HodlrMatrix P = HodlrMatrix::symmetric(m, products, relative, 32, 1);
  const HodlrMatrix D(A, relative * scale, 32, 1);
  // Rounds of 8 alone: 71 blocks and 1056 columns (ranks 144 peeled, 166 direct).
  CHECK(blocks <= 55);
  CHECK(columns <= 1100);
  CHECK(P.max_rank() <= D.max_rank() + 8);
  std::srand(6);
  const Eigen::VectorXd v = Eigen::VectorXd::Random(m);
  CHECK((P.multiply(v) - A * v).norm() <= 100 * relative * scale * v.norm());
}

TEST_CASE("HODLR: a Gauss-Seidel pass and the products with the blocks shared among threads are the dense ones and the same bits in any thread count", "[hodlr]") {
  // A surface's kernel (surface_kernel): the blocks of the top bisections are large enough to
  // be shared among three threads (la/hodlr.cpp: 2^14 entries each at least; two on a 2-core
  // machine, as no more threads than cores share them). The pass and the product must be the
  // dense ones, and bit for bit those of one thread: the blocks are cut into the cores' slices
  // whatever the threads (blas_threads::slices()), so that the sweeps' choice of threads
  // (la/thread_choice.hpp) and OMP_NUM_THREADS move no result. 30 x 30 points: slices begin at
  // rows off Eigen's packets, where it sums some rows one by one (a split by the threads moved
  // bits there; on 32 x 32 every slice began on a packet and it passed).
  const int m = 30 * 30;
  const Eigen::MatrixXd A = surface_kernel(30);
  const HodlrMatrix P = HodlrMatrix::symmetric(m, [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(A * X); }, 1e-13, 32, 1);
  REQUIRE(P.max_rank() * (m / 2) >= 3 << 14);  // the top blocks are shared by three threads
  std::srand(8);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Random(m), q = Eigen::VectorXd::Random(m);
  const auto update = [](double y, double x) { return -0.4 * y + 0.1 * x; };
  // The dense pass: x_i from y_i, then y follows with A's column i.
  Eigen::VectorXd x_dense = x0, y_dense = A * x0 + q;
  for (int i = 0; i < m; ++i) {
    const double old = x_dense[i];
    x_dense[i] = update(y_dense[i], old);
    y_dense += A.col(i) * (x_dense[i] - old);
  }
  const auto pass = [&](Eigen::VectorXd& x, Eigen::VectorXd& y) {
    x = x0, y = A * x0 + q;
    P.gauss_seidel([&](Eigen::Index i) { x[i] = update(y[i], x[i]); }, x, y);
  };
  const int threads_before = omp_get_max_threads();
  Eigen::VectorXd x1, y1, x3, y3;
  omp_set_num_threads(1);
  REQUIRE(blas_threads::products() == 1);
  pass(x1, y1);
  const Eigen::VectorXd product1 = P.multiply(x0);
  omp_set_num_threads(3);
  if (blas_threads::products() != std::min(3, omp_get_num_procs()))  // keep_one() is for the whole process
    WARN("an earlier test in this process kept one thread (tests/la/test_blas_threads.cpp): run this test alone");
  if (omp_get_num_procs() == 1) WARN("one core: the blocks are not shared");
  pass(x3, y3);
  const Eigen::VectorXd product3 = P.multiply(x0);
  omp_set_num_threads(threads_before);
  const double scale = A.diagonal().maxCoeff();
  CHECK((x_dense - x0).norm() > 0.1 * x0.norm());  // the pass moved x
  for (const Eigen::VectorXd* x : {&x1, &x3}) CHECK((*x - x_dense).norm() <= 1e-11 * x_dense.norm());
  for (const Eigen::VectorXd* y : {&y1, &y3}) CHECK((*y - y_dense).norm() <= 1e-11 * y_dense.norm());
  CHECK((y3 - A * x3 - q).norm() <= 1e-11 * scale * x3.norm());
  CHECK(x3 == x1);
  CHECK(y3 == y1);
  for (const Eigen::VectorXd* p : {&product1, &product3}) CHECK((*p - A * x0).norm() <= 1e-11 * scale * x0.norm());
  CHECK(product3 == product1);
  // The sweeps' limit (blas_threads::Limit) is one more thread count: the same bits again.
  Eigen::VectorXd x_limited, y_limited, product_limited;
  {
    const blas_threads::Limit one(1);
    CHECK(blas_threads::products() == 1);
    pass(x_limited, y_limited);
    product_limited = P.multiply(x0);
  }
  CHECK(blas_threads::products() == blas_threads::most_products());
  CHECK(x_limited == x1);
  CHECK(product_limited == product1);
}

TEST_CASE("HODLR: a Gauss-Seidel pass by blocks sweeps each largest subtree within the rows several times before the next",
          "[hodlr]") {
  // 1024 rows bisected down to leaves of 32: the largest subtrees of at most 150 rows are the
  // eight of 128. The pass by blocks must be the dense pass over those eight runs of rows,
  // each swept three times before the next (y keeping up everywhere), not over runs of 64 or
  // 256; blocks of fewer rows than a leaf are the leaves.
  const int m = 32 * 32;
  const Eigen::MatrixXd A = surface_kernel(32);
  const HodlrMatrix P = HodlrMatrix::symmetric(m, [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(A * X); }, 1e-13, 32, 1);
  std::srand(11);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Random(m), q = Eigen::VectorXd::Random(m);
  const auto update = [](double y, double x) { return -0.4 * y + 0.1 * x; };
  const auto dense_pass = [&](int rows, int sweeps, Eigen::VectorXd& x, Eigen::VectorXd& y) {
    x = x0, y = A * x0 + q;
    for (int begin = 0; begin < m; begin += rows)
      for (int k = 0; k < sweeps; ++k)
        for (int i = begin; i < begin + rows; ++i) {
          const double old = x[i];
          x[i] = update(y[i], old);
          y += A.col(i) * (x[i] - old);
        }
  };
  const auto pass = [&](const SweepBlocks& blocks, Eigen::VectorXd& x, Eigen::VectorXd& y) {
    x = x0, y = A * x0 + q;
    P.gauss_seidel([&](Eigen::Index i) { x[i] = update(y[i], x[i]); }, x, y, blocks);
  };
  Eigen::VectorXd x128, y128, x64, y64, x256, y256, x32, y32, x, y, x_leaf, y_leaf, x1, y1, x_plain, y_plain;
  dense_pass(128, 3, x128, y128);
  dense_pass(32, 3, x32, y32);
  dense_pass(64, 3, x64, y64);
  dense_pass(256, 3, x256, y256);
  dense_pass(m, 1, x_plain, y_plain);
  pass({3, 150}, x, y);
  pass({1, 150}, x1, y1);
  pass({3, 10}, x_leaf, y_leaf);
  const double scale = A.diagonal().maxCoeff();
  CHECK((x - x128).norm() <= 1e-11 * x128.norm());
  CHECK((y - y128).norm() <= 1e-11 * y128.norm());
  CHECK((y - A * x - q).norm() <= 1e-11 * scale * x.norm());  // y keeps up with x after the pass
  CHECK((x64 - x128).norm() > 1e-6 * x128.norm());            // the runs' length shows in the result
  CHECK((x256 - x128).norm() > 1e-6 * x128.norm());
  CHECK((x_leaf - x32).norm() <= 1e-11 * x32.norm());
  CHECK((x1 - x_plain).norm() <= 1e-11 * x_plain.norm());  // one sweep per block: the plain pass
  CHECK((x - x_plain).norm() > 1e-6 * x_plain.norm());
}

TEST_CASE("HODLR: truncated to a looser tolerance the ranks fall and the products stay within it", "[hodlr]") {
  const int m = 600;
  const Eigen::MatrixXd A = 1e4 * kernel_matrix(m);  // the tolerance is relative to the diagonal
  const HodlrMatrix H(A, 1e-14 * 3e4, 32, 2);
  const double scale = H.diagonal_scale();
  REQUIRE(scale == Approx(3e4));
  std::srand(5);
  const Eigen::MatrixXd X = Eigen::MatrixXd::Random(m, 4);
  const auto error = [&](const HodlrMatrix& T) {
    double e = 0;
    for (int k = 0; k < X.cols(); ++k) e = std::max(e, (T.multiply(X.col(k)) - A * X.col(k)).norm() / X.col(k).norm());
    return e;
  };
  int previous = H.max_rank() + 1;
  for (double relative : {1e-13, 1e-8, 1e-4, 1e-2}) {
    INFO("truncated to " << relative);
    const HodlrMatrix T = H.truncated(relative);
    CHECK(T.size() == m);
    CHECK(T.max_rank() < previous);  // each looser tolerance drops rank somewhere
    previous = T.max_rank();
    // Each block within relative * scale (Frobenius); the levels' blocks add up on a product.
    CHECK(error(T) <= 20 * relative * scale);
    if (relative >= 1e-8) CHECK(error(T) >= 1e-2 * relative * scale);  // truncated to it, not kept whole
    // Its factorization preconditions A: one refinement step with A's products gains the
    // truncation's error, relative to the first residual.
    const Eigen::VectorXd b = X.col(0);
    const Eigen::VectorXd x0 = HodlrSolver(T).solve(b);
    const Eigen::VectorXd r = b - A * x0;
    const Eigen::VectorXd x1 = x0 + HodlrSolver(T).solve(r);
    CHECK((b - A * x1).norm() <= 1e-2 * r.norm() + 1e-14 * b.norm());
  }
  // Exact rank one blocks stay exact at any tolerance below their size.
  Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(m, 1.0, 2.0);
  const Eigen::MatrixXd B = v * v.transpose() + 10.0 * Eigen::MatrixXd::Identity(m, m);
  const HodlrMatrix T = HodlrMatrix(B, 1e-12, 32, 2).truncated(1e-6);
  CHECK(T.max_rank() == 1);
  CHECK((T.multiply(X.col(1)) - B * X.col(1)).norm() <= 1e-11 * (B * X.col(1)).norm());
}

TEST_CASE("HODLR: plus a low-rank matrix is the sum to the tolerance and takes the rank back when subtracted", "[hodlr]") {
  // Condensation::change_springs adds A G A^T (the columns of a few pairs) to W0 this way.
  const int m = 600;
  const Eigen::MatrixXd A = 1e3 * kernel_matrix(m);
  const HodlrMatrix H(A, 1e-13 * 3e3, 32, 2);
  std::srand(11);
  const Eigen::MatrixXd X = Eigen::MatrixXd::Random(m, 7), Y = Eigen::MatrixXd::Random(m, 7);
  const Eigen::MatrixXd B = A + 1e2 * X * Y.transpose();
  const HodlrMatrix S = H.plus(1e2 * X, Y, 1e-13);
  REQUIRE(S.size() == m);
  CHECK(S.granule() == H.granule());
  const Eigen::MatrixXd Z = Eigen::MatrixXd::Random(m, 3);
  // Products of a block of columns, and of each alone, against the dense sum.
  const Eigen::MatrixXd SZ = S.multiply_block(Z);
  CHECK((SZ - B * Z).norm() <= 1e-11 * (B * Z).norm());
  for (int k = 0; k < Z.cols(); ++k) CHECK((S.multiply(Z.col(k)) - SZ.col(k)).norm() <= 1e-14 * SZ.col(k).norm());
  // The leaves took their share: the pairs' diagonal blocks are B's.
  CHECK((S.diagonal_block(100, 2) - B.block(100, 100, 2, 2)).norm() <= 1e-12 * B.block(100, 100, 2, 2).norm());
  // A generic rank-7 term raises every off-diagonal rank by up to 7; taken away, the
  // recompression finds the ranks of A again (within a few of round-off's).
  CHECK(S.max_rank() > H.max_rank());
  CHECK(S.max_rank() <= H.max_rank() + 7);
  const HodlrMatrix back = S.plus(-1e2 * X, Y, 1e-13);
  CHECK(back.max_rank() <= H.max_rank() + 2);
  CHECK((back.multiply_block(Z) - A * Z).norm() <= 1e-11 * (A * Z).norm());
  // Solves with the sum agree with the dense ones.
  const Eigen::MatrixXd sol = HodlrSolver(S).solve(Z);
  CHECK((B * sol - Z).norm() <= 1e-9 * Z.norm());
}

TEST_CASE("HODLR: a symmetric matrix plus a symmetric low-rank term stays symmetric and stored once", "[hodlr]") {
  // W0 peeled, then changed by Woodbury's A G A^T (Condensation::change_springs).
  const int m = 640;
  const Eigen::MatrixXd A = kernel_matrix(m);
  const auto products = [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(A * X); };
  const HodlrMatrix P = HodlrMatrix::symmetric(m, products, 1e-13, 32, 2);
  std::srand(12);
  const Eigen::MatrixXd X = Eigen::MatrixXd::Random(m, 5), G0 = Eigen::MatrixXd::Random(5, 5);
  const Eigen::MatrixXd G = G0 + G0.transpose();
  const Eigen::MatrixXd B = A + X * G * X.transpose();
  const HodlrMatrix S = P.plus(X * G, X, 1e-13);
  const Eigen::MatrixXd Z = Eigen::MatrixXd::Random(m, 3);
  CHECK((S.multiply_block(Z) - B * Z).norm() <= 1e-11 * (B * Z).norm());
  // Symmetric to round-off: z^T S x = x^T S z.
  const double zSx = Z.col(0).dot(S.multiply(Z.col(1))), xSz = Z.col(1).dot(S.multiply(Z.col(0)));
  CHECK(std::abs(zSx - xSz) <= 1e-13 * std::abs(zSx));
  // Rank 5 more at most, each block once: 5 columns more in U21 and V21 at each of the 5
  // levels of bisections add 25 m doubles (both blocks stored: 50 m).
  CHECK(S.max_rank() <= P.max_rank() + 5);
  CHECK(S.stored() <= P.stored() + 30 * m);
  // Solves with it agree with the dense ones.
  CHECK((B * HodlrSolver(S).solve(Z) - Z).norm() <= 1e-9 * Z.norm());
}
