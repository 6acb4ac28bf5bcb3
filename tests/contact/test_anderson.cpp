// Anderson acceleration (anderson.hpp) on affine fixed-point maps y -> A y + b, where it is
// GMRES in disguise: with as many differences as unknowns it finds the fixed point in about
// as many iterations, and the u = W y + q carried along stays the product of the mixed y.
#include "rccm/contact/anderson.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

using namespace rccm;

namespace {

/// A contraction A (spectral radius 0.95: plain iteration needs ~500 steps for 1e-10),
/// b, and the fixed point y* = (I - A)^-1 b.
struct AffineMap {
  explicit AffineMap(int n, std::mt19937& gen) {
    std::uniform_real_distribution<double> U(-1, 1);
    const Eigen::MatrixXd B = Eigen::MatrixXd::NullaryExpr(n, n, [&]() { return U(gen); });
    A = B + B.transpose();
    A *= 0.95 / A.eigenvalues().cwiseAbs().maxCoeff();
    b = Eigen::VectorXd::NullaryExpr(n, [&]() { return U(gen); });
    fixed_point = (Eigen::MatrixXd::Identity(n, n) - A).partialPivLu().solve(b);
  }
  Eigen::MatrixXd A;
  Eigen::VectorXd b, fixed_point;
};

/// Iterations of y -> A y + b, mixed with `depth` differences, until |y - y*| <= 1e-10 |y*|
/// (at most `limit`); u = W y + q is carried along and checked after every mix.
int iterations_to_fixed_point(const AffineMap& map, int depth, int limit, std::mt19937& gen) {
  const Eigen::Index n = map.b.size();
  std::uniform_real_distribution<double> U(-1, 1);
  const Eigen::MatrixXd W = Eigen::MatrixXd::NullaryExpr(n, n, [&]() { return U(gen); });
  const Eigen::VectorXd q = Eigen::VectorXd::NullaryExpr(n, [&]() { return U(gen); });
  AndersonMixing anderson(depth);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n);
  for (int k = 1; k <= limit; ++k) {
    const Eigen::VectorXd y_in = y;
    y = map.A * y_in + map.b;
    Eigen::VectorXd u = W * y + q;
    anderson.mix(y_in, y, u);
    REQUIRE((u - (W * y + q)).norm() <= 1e-11 * (1 + u.norm()));
    if ((y - map.fixed_point).norm() <= 1e-10 * map.fixed_point.norm()) return k;
  }
  return limit + 1;
}

}  // namespace

TEST_CASE("Anderson mixing on an affine map: as many differences as unknowns find the fixed point in about as many steps",
          "[anderson]") {
  std::mt19937 gen(11);
  for (int trial = 0; trial < 5; ++trial) {
    const int n = 10 + 2 * trial;
    const AffineMap map(n, gen);
    INFO("trial " << trial << ", n = " << n);
    // GMRES on I - A converges in n steps; the mix needs one sweep more to start, and a few
    // for round-off of its least-squares problem.
    CHECK(iterations_to_fixed_point(map, n, 3 * n, gen) <= n + 4);
    // Plain iteration (depth 0) contracts by 0.95 per step: ~450 steps for 1e-10.
    CHECK(iterations_to_fixed_point(map, 0, 3 * n, gen) > 3 * n);
  }
}

TEST_CASE("Anderson mixing with a short history still converges, and faster than the plain iteration", "[anderson]") {
  std::mt19937 gen(12);
  const AffineMap map(60, gen);
  const int plain = iterations_to_fixed_point(map, 0, 2000, gen);
  const int mixed = iterations_to_fixed_point(map, 5, 2000, gen);
  INFO("plain " << plain << " mixed " << mixed);
  CHECK(plain <= 2000);
  CHECK(mixed < plain / 2);
}

TEST_CASE("Anderson mixing of a sweep that repeats the same step (every difference zero) leaves the sweep's iterate",
          "[anderson]") {
  // A sweep stagnating at round-off can move y by the very same step each time: f - f_prev
  // is exactly zero, nothing is left to combine, and the least-squares solve of a rank-0
  // factorization is not finite (FC2D_SliderCrankLagrangian00000 once turned to NaN so).
  AndersonMixing anderson(5);
  Eigen::VectorXd y = Eigen::VectorXd::Constant(4, 0.07);
  const Eigen::VectorXd u = Eigen::VectorXd::Constant(4, 12.0);
  Eigen::VectorXd step(4);
  step << 1e-17, -3e-18, 2e-16, 0;
  for (int k = 0; k < 6; ++k) {
    const Eigen::VectorXd y_in = y;
    y = y_in + step;
    Eigen::VectorXd u_mixed = u;
    anderson.mix(y_in, y, u_mixed);
    INFO("sweep " << k);
    REQUIRE(y == y_in + step);
    REQUIRE(u_mixed == u);
  }
}

TEST_CASE("Anderson mixing returns the weight of its combination: the 1-norm of the coefficients that the mixed y shows",
          "[anderson]") {
  // The solver multiplies these weights up to decide whether the mixed u, which carries the
  // sweeps' round-off times them, can be trusted without a fresh product (solver_tuning.hpp).
  // Independently of the mix: its y is G_k - dG gamma, with dG the differences of the sweeps'
  // results kept in the test, so gamma is the least-squares solution of dG gamma = G_k - y.
  std::mt19937 gen(13);
  const AffineMap map(10, gen);
  const int depth = 3;
  AndersonMixing anderson(depth);
  std::vector<Eigen::VectorXd> G;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(10);
  for (int k = 0; k < 8; ++k) {
    const Eigen::VectorXd y_in = y;
    y = map.A * y_in + map.b;
    G.push_back(y);
    Eigen::VectorXd u = y;
    const double weight = anderson.mix(y_in, y, u);
    INFO("sweep " << k << ", weight " << weight);
    if (k == 0) {
      REQUIRE(weight == 0);  // nothing to combine yet
      continue;
    }
    const int count = std::min(k, depth);
    Eigen::MatrixXd dG(10, count);
    for (int j = 0; j < count; ++j) dG.col(j) = G[k - j] - G[k - j - 1];
    const Eigen::VectorXd gamma = dG.colPivHouseholderQr().solve(G[k] - y);
    REQUIRE((dG * gamma - (G[k] - y)).norm() <= 1e-10 * (1 + y.norm()));
    CHECK(weight == Approx(gamma.lpNorm<1>()).epsilon(1e-6));
    CHECK(weight > 0);
  }
}
