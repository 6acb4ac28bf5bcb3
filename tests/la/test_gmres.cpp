#include "rccm/la/gmres.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

using namespace rccm;

TEST_CASE("GMRES: exact in n iterations without preconditioning, a few with a nearby inverse", "[gmres]") {
  const int n = 40;
  std::srand(7);
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n) * 4 + Eigen::MatrixXd::Random(n, n);  // nonsymmetric
  const Eigen::VectorXd x_exact = Eigen::VectorXd::Random(n), b = A * x_exact;
  const LinearMap apply_A = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return A * v; };

  const LinearMap identity = [](const Eigen::VectorXd& v) { return v; };
  const GmresResult plain = gmres(apply_A, identity, b, 1e-13, n);
  CHECK(plain.iterations <= n);
  CHECK((plain.x - x_exact).norm() <= 1e-10 * x_exact.norm());
  CHECK((b - A * plain.x).norm() == Approx(plain.residual).margin(1e-11 * b.norm()));

  // The inverse of A with two rows changed: A M - I has rank 2, GMRES ends in 3 iterations.
  Eigen::MatrixXd A_old = A;
  A_old.row(3) += Eigen::RowVectorXd::Random(n);
  A_old.row(17) *= 1.5;
  const Eigen::MatrixXd M = A_old.inverse();
  const LinearMap apply_M = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return M * v; };
  const GmresResult pre = gmres(apply_A, apply_M, b, 1e-13, n);
  CHECK(pre.iterations <= 3);
  CHECK((pre.x - x_exact).norm() <= 1e-10 * x_exact.norm());
  // x is the combination of the preconditioned vectors: recovered from M and the coefficients.
  CHECK(pre.coefficients.size() == pre.iterations);
}

TEST_CASE("GMRES: a zero right-hand side gives x = 0 without calling A", "[gmres]") {
  int calls = 0;
  const LinearMap A = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { ++calls; return v; };
  const GmresResult r = gmres(A, A, Eigen::VectorXd::Zero(5), 1e-12, 5);
  CHECK(r.x.isZero(0.0));
  CHECK(calls == 0);
}

TEST_CASE("GMRES: a singular operator on b stops at once with x = 0", "[gmres]") {
  const LinearMap zero = [](const Eigen::VectorXd& v) -> Eigen::VectorXd { return Eigen::VectorXd::Zero(v.size()); };
  const LinearMap identity = [](const Eigen::VectorXd& v) { return v; };
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(4);
  const GmresResult r = gmres(zero, identity, b, 1e-12, 4);
  CHECK(r.iterations == 0);
  CHECK(r.x.isZero(0.0));
  CHECK(r.residual == Approx(b.norm()));
}
