// The Delassus operators (contact/delassus): the sparse W0 is the same operator as the dense
// one, and the bipotential solver gives the same solution on either; the solvers that need
// the dense W0 say so.
#include "rccm/contact/contact_solver.hpp"
#include "rccm/contact/solver_tuning.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/base/format.hpp"
#include "rccm/la/blas_threads.hpp"
#include "random_problem.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <random>

using namespace rccm;

namespace {

/// A multibody-like Delassus matrix W = G M^-1 G^T of n 2D contacts between `bodies` rigid
/// bodies (3 degrees of freedom each), every contact touching two of them: sparse (a contact
/// couples only with the contacts of its two bodies) and positive semi-definite, plus a small
/// compliance so that it is definite.
Eigen::SparseMatrix<double> multibody_W(int n, int bodies, std::mt19937& gen) {
  std::uniform_real_distribution<double> U(-1, 1);
  std::uniform_int_distribution<int> body(0, bodies - 1);
  std::vector<Eigen::Triplet<double>> g;
  for (int c = 0; c < n; ++c) {
    const int a = body(gen);
    int b = body(gen);
    if (b == a) b = (a + 1) % bodies;
    for (int k = 0; k < 2; ++k)
      for (int d = 0; d < 3; ++d) {
        g.emplace_back(2 * c + k, 3 * a + d, U(gen));
        g.emplace_back(2 * c + k, 3 * b + d, U(gen));
      }
  }
  Eigen::SparseMatrix<double> G(2 * n, 3 * bodies);
  G.setFromTriplets(g.begin(), g.end());
  Eigen::SparseMatrix<double> I(2 * n, 2 * n);
  I.setIdentity();
  return Eigen::SparseMatrix<double>(G * G.transpose()) + 0.05 * I;
}

}  // namespace

TEST_CASE("Sparse and dense W0 are the same operator", "[delassus]") {
  std::mt19937 gen(11);
  const Eigen::SparseMatrix<double> S = multibody_W(40, 25, gen);
  const SparseDelassus sparse(S);
  const DenseDelassus dense{Eigen::MatrixXd(S)};
  REQUIRE(S.nonZeros() < S.rows() * S.cols() / 4);  // it is sparse
  CHECK(sparse.size() == dense.size());
  CHECK(sparse.diagonal_scale() == dense.diagonal_scale());
  CHECK(sparse.dense() == nullptr);
  // The run report's line: a nonzero is its value and an int row index (12 bytes).
  const std::string rows = std::to_string(S.rows()) + " x " + std::to_string(S.rows());
  CHECK(sparse.storage() == "sparse, " + rows + " (" + fmt("%.3g", 12e-6 * double(S.nonZeros())) + " MB, " +
                                std::to_string(S.nonZeros()) + " nonzeros)");
  CHECK(dense.storage() == "dense, " + rows + " (" + fmt("%.3g", 8e-6 * double(S.rows() * S.rows())) + " MB)");
  std::uniform_real_distribution<double> U(-1, 1);
  const Eigen::VectorXd y = Eigen::VectorXd::NullaryExpr(S.rows(), [&]() { return U(gen); });
  Eigen::VectorXd us(S.rows()), ud(S.rows());
  sparse.multiply(y, us);
  dense.multiply(y, ud);
  CHECK((us - ud).norm() <= 1e-14 * ud.norm());
  for (Eigen::Index first : {Eigen::Index(0), Eigen::Index(14), S.rows() - 2}) {
    CHECK((sparse.block(first, 2) - dense.block(first, 2)).norm() == 0.0);
    LocalVector dy(2);
    dy << U(gen), U(gen);
    sparse.add_response(first, dy, us);
    dense.add_response(first, dy, ud);
    CHECK((us - ud).norm() <= 1e-14 * ud.norm());
  }
}

TEST_CASE("A Gauss-Seidel pass by blocks sweeps each run of pairs several times before the next on dense and sparse W0",
          "[delassus]") {
  // Blocks of at most 7 rows over pairs of 2: runs of 3 pairs (6 rows), each swept 3 times
  // (u keeping up with y everywhere) before the next; the dense W0's inlined pass answers a
  // run's changes on the other rows once after its sweeps, the same sums in another order.
  std::mt19937 gen(12);
  const Eigen::SparseMatrix<double> S = multibody_W(40, 25, gen);
  const Eigen::MatrixXd W(S);
  const SparseDelassus sparse(S);
  const DenseDelassus dense{W};
  const Eigen::Index m = W.rows();
  std::uniform_real_distribution<double> U(-1, 1);
  const Eigen::VectorXd y0 = Eigen::VectorXd::NullaryExpr(m, [&]() { return U(gen); });
  const Eigen::VectorXd q = Eigen::VectorXd::NullaryExpr(m, [&]() { return U(gen); });
  const auto update = [](Eigen::VectorXd& y, const Eigen::VectorXd& u, int i) {
    y.segment(2 * i, 2) = -0.4 * u.segment(2 * i, 2) + 0.1 * y.segment(2 * i, 2);
  };
  const auto reference = [&](Eigen::Index rows, int sweeps, Eigen::VectorXd& y, Eigen::VectorXd& u) {
    y = y0, u = W * y0 + q;
    for (Eigen::Index begin = 0; begin < m; begin += rows)
      for (int k = 0; k < sweeps; ++k)
        for (Eigen::Index first = begin; first < std::min(begin + rows, m); first += 2) {
          const Eigen::Vector2d old = y.segment(first, 2);
          update(y, u, int(first / 2));
          u += W.middleCols(first, 2) * (y.segment(first, 2) - old);
        }
  };
  Eigen::VectorXd y6, u6, y8, u8, y_plain, u_plain;
  reference(6, 3, y6, u6);
  reference(8, 3, y8, u8);
  reference(m, 1, y_plain, u_plain);
  CHECK((y8 - y6).norm() > 1e-6 * y6.norm());  // the runs' length shows in the result
  CHECK((y_plain - y6).norm() > 1e-6 * y6.norm());
  const SweepBlocks blocks{3, 7};
  CHECK(block_rows(blocks, 2, m) == 6);
  CHECK(block_rows({3, 1}, 3, m) == 3);  // a pair at least
  CHECK(block_rows({1, 7}, 2, m) == m);  // swept once: the plain pass, one block
  for (int variant = 0; variant < 3; ++variant) {
    Eigen::VectorXd y = y0, u = W * y0 + q;
    const auto visit = [&](int i) { update(y, u, i); };
    if (variant == 0) gauss_seidel_pass<2>(dense, visit, y, u, blocks);  // dense, inlined
    if (variant == 1) dense.gauss_seidel(2, visit, y, u, blocks);         // pair by pair with add_response
    if (variant == 2) gauss_seidel_pass<2>(sparse, visit, y, u, blocks);
    INFO("variant " << variant);
    CHECK((y - y6).norm() <= 1e-12 * y6.norm());
    CHECK((u - u6).norm() <= 1e-12 * u6.norm());
    CHECK((u - W * y - q).norm() <= 1e-12 * u.norm());
  }
}

TEST_CASE("A compressed W0's products, blocks and Gauss-Seidel passes are the dense ones to its accuracy", "[delassus]") {
  // A smooth symmetric kernel (the flexibility of a line decays slowly): 2 x 150 rows, leaves of 64.
  const int n = 150, m = 2 * n;
  Eigen::MatrixXd W(m, m);
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) W(a, b) = (a % 2 == b % 2 ? 1.0 : 0.3) / (1.0 + std::abs(a / 2 - b / 2) / 4.0);
  const DenseDelassus plain{W};
  const CompressedDelassus compressed{
      HodlrMatrix::symmetric(m, [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(W * X); }, 1e-13, 64, 2)};
  REQUIRE(plain.compressed() == nullptr);
  REQUIRE(compressed.compressed() != nullptr);
  CHECK(compressed.dense() == nullptr);
  CHECK(compressed.size() == m);
  CHECK(std::abs(compressed.diagonal_scale() - plain.diagonal_scale()) <= 1e-13 * plain.diagonal_scale());
  CHECK(3 * compressed.compressed()->stored() < 2 * m * m);  // it is compressed
  std::mt19937 gen(4);
  std::uniform_real_distribution<double> U(-1, 1);
  const Eigen::VectorXd y = Eigen::VectorXd::NullaryExpr(m, [&]() { return U(gen); });
  Eigen::VectorXd up(m), uc(m);
  plain.multiply(y, up);
  compressed.multiply(y, uc);
  CHECK((uc - W * y).norm() <= 1e-12 * W.norm() * y.norm());
  for (Eigen::Index first : {Eigen::Index(0), Eigen::Index(18), Eigen::Index(m - 2)}) {
    CHECK((compressed.block(first, 2) - plain.block(first, 2)).norm() <= 1e-12);
    LocalVector dy(2);
    dy << U(gen), U(gen);
    Eigen::VectorXd rc = uc, rp = uc;
    compressed.add_response(first, dy, rc);
    plain.add_response(first, dy, rp);
    CHECK((rc - rp).norm() <= 1e-12 * dy.norm());
  }
  // A Gauss-Seidel pass whose updates read u (y_i from u_i): the same sequence of y and u
  // through the hierarchy as pair by pair with W0's columns, and u - W0 y kept.
  const Eigen::VectorXd q = Eigen::VectorXd::NullaryExpr(m, [&]() { return U(gen); });
  Eigen::VectorXd yp = y, yc = y, upass = W * y + q, ucompressed = upass;
  const auto pass = [&](const DelassusOperator& op, Eigen::VectorXd& yy, Eigen::VectorXd& uu) {
    op.gauss_seidel(2, [&](int i) { yy.segment(2 * i, 2) = -0.4 * uu.segment(2 * i, 2) + 0.1 * yy.segment(2 * i, 2); }, yy, uu,
                    SweepBlocks{});
  };
  pass(plain, yp, upass);
  pass(compressed, yc, ucompressed);
  CHECK((yp - y).norm() > 0.1 * y.norm());  // the pass moved y
  CHECK((yc - yp).norm() <= 1e-11 * yp.norm());
  CHECK((ucompressed - upass).norm() <= 1e-11 * upass.norm());
  CHECK((upass - W * yp - q).norm() <= 1e-12 * upass.norm());
  CHECK((ucompressed - W * yc - q).norm() <= 1e-12 * ucompressed.norm());
  // The exact step's preconditioner: W0 truncated to tuning::hodlr_preconditioner_accuracy of
  // its diagonal (lower ranks), made at the first call and kept.
  const HodlrMatrix* P = compressed.compressed_preconditioner();
  REQUIRE(P != nullptr);
  CHECK(compressed.compressed_preconditioner() == P);
  CHECK(P->max_rank() < compressed.compressed()->max_rank());
  CHECK((P->multiply(y) - W * y).norm() <= 10 * tuning::hodlr_preconditioner_accuracy * plain.diagonal_scale() * y.norm());
  // The run report's line: the dense W0's m^2 doubles, the compressed one's stored doubles
  // and their share of m^2, its largest rank, the threads of its large blocks.
  CHECK(plain.storage() == "dense, 300 x 300 (0.72 MB)");  // 90 000 doubles
  const HodlrMatrix& H = *compressed.compressed();
  CHECK(compressed.storage() == "compressed (HODLR), 300 x 300 (" + fmt("%.3g", 8e-6 * double(H.stored())) + " MB, " +
                                    fmt("%.0f", 100.0 * double(H.stored()) / (m * m)) + " % of dense), largest rank " +
                                    std::to_string(H.max_rank()) + ", its large blocks in " +
                                    std::to_string(blas_threads::products()) + " thread(s)");
}

TEST_CASE("The bipotential solver on a sparse W0: the solution it finds on the dense one", "[delassus]") {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> U(-1, 1), P(0, 1);
  for (bool springs : {false, true}) {
    const int n = 60, m = 2 * n;
    const SparseDelassus sparse(multibody_W(n, 30, gen));
    const DenseDelassus dense{Eigen::MatrixXd(sparse.matrix())};
    ContactProblem pb;
    pb.layout.dim = 2;
    pb.q0 = Eigen::VectorXd::NullaryExpr(m, [&]() { return U(gen); });
    pb.mubar = Eigen::VectorXd::NullaryExpr(n, [&]() { return 0.6 * P(gen); });
    pb.g0 = Eigen::VectorXd::Zero(n);
    pb.u_ref = Eigen::VectorXd::NullaryExpr(m, [&]() { return 0.05 * U(gen); });
    pb.Dref = pb.Dbeta = Eigen::VectorXd::Zero(m);
    if (springs) {  // springs softer than W0's pairs (I - W0_ii E invertible), D(beta) <= Dref
      const double k = 0.2 / sparse.diagonal_scale();
      pb.Dref = Eigen::VectorXd::Constant(m, k);
      for (int i = 0; i < n; ++i) pb.Dbeta.segment(2 * i, 2).setConstant(k * P(gen));
    }
    SolverParams params;
    params.tolerance = 1e-12;
    params.max_iterations = 20000;
    ContactProblem on_dense = pb, on_sparse = pb;
    on_dense.W0 = &dense;
    on_sparse.W0 = &sparse;
    const ContactSolution d = make_contact_solver(params)->solve(on_dense, {}, {});
    const ContactSolution s = make_contact_solver(params)->solve(on_sparse, {}, {});
    INFO("springs " << springs << ": dense " << d.iterations << " passes, sparse " << s.iterations);
    REQUIRE(s.converged);
    REQUIRE(d.converged);
    testing::require_solution(on_sparse, s);
    CHECK(s.exact_solves == 0);  // the exact step needs the dense W0: sweeps only
    CHECK((s.Rbar - d.Rbar).norm() <= 1e-9 * (1 + d.Rbar.norm()));
    CHECK((s.u - d.u).norm() <= 1e-9 * (1 + d.u.norm()));
  }
}

TEST_CASE("rccm and newton need the dense W0 and say so", "[delassus]") {
  std::mt19937 gen(2);
  const SparseDelassus sparse(multibody_W(10, 8, gen));
  ContactProblem pb;
  pb.layout.dim = 2;
  pb.W0 = &sparse;
  pb.q0 = -Eigen::VectorXd::Ones(20);
  pb.mubar = Eigen::VectorXd::Constant(10, 0.3);
  pb.g0 = Eigen::VectorXd::Zero(10);
  pb.u_ref = pb.Dref = pb.Dbeta = Eigen::VectorXd::Zero(20);
  for (ContactMethod method : {ContactMethod::Rccm, ContactMethod::Newton}) {
    SolverParams params;
    params.method = method;
    CHECK_THROWS_AS(make_contact_solver(params)->solve(pb, {}, {}), SolveError);
  }
}
