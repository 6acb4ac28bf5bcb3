// A contact pair's local problem (contact/pair_block): the exact 2D solution of its case
// satisfies the law R = proj(R - rho s(Wb R + c), K_mubar), is the limit of the iterated
// predictor-corrector, and lands in each regime where the closed form says.
#include "rccm/contact/pair_block.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/contact/delassus.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace rccm;

namespace {

/// A pair of random SPD flexibility Wb (with off-diagonal coupling), slip and gap shift, and mubar.
PairBlock<2> random_pair(std::mt19937& gen) {
  std::uniform_real_distribution<double> U(-1, 1), P(0, 1);
  PairBlock<2> b;
  const Eigen::Matrix2d B = Eigen::Matrix2d::NullaryExpr([&]() { return U(gen); });
  b.Wii = B * B.transpose() + 0.2 * Eigen::Matrix2d::Identity();
  b.E.setZero();
  b.M.setIdentity();
  b.Wb = b.Wii;
  b.shift = Eigen::Vector2d(0.1 * U(gen), 0.2 * P(gen));
  b.mubar = 0.8 * P(gen);
  b.rho = 1.0 / b.Wb.eigenvalues().real().maxCoeff();
  b.prescribed = false;
  return b;
}

/// The law's residual |R - proj(R - rho s(u), K_mubar)| at u = Wb R + c, relative.
double law_residual(const PairBlock<2>& b, const Eigen::Vector2d& c, const Eigen::Vector2d& R) {
  const Eigen::Vector2d u = b.Wb * R + c;
  return (R - project_cone(b.predictor(R, u), b.mubar)).norm() / (1 + R.norm());
}

}  // namespace

TEST_CASE("the exact 2D local solve meets the law and is the predictor-corrector's limit", "[pair-block]") {
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> U(-1, 1);
  int seen[3] = {0, 0, 0};
  for (int trial = 0; trial < 5000; ++trial) {
    const PairBlock<2> b = random_pair(gen);
    const Eigen::Vector2d c(U(gen), U(gen));
    Eigen::Vector2d exact = Eigen::Vector2d::Zero(), iterated = Eigen::Vector2d::Zero();
    const Status s = solve_pair<2>(b, c, exact, 100, 1e-12, 0, 0);
    const Status s_it = iterate_pair<2>(b, c, iterated, 100000, 1e-15, 0, 0);
    INFO("trial " << trial << ": exact " << exact.transpose() << " (" << status_name(s) << "), iterated "
                  << iterated.transpose() << " (" << status_name(s_it) << ")");
    REQUIRE(law_residual(b, c, exact) <= 1e-13);
    REQUIRE((exact - iterated).norm() <= 1e-9 * (1 + exact.norm()));
    ++seen[static_cast<int>(s)];
  }
  CHECK(seen[0] > 300);  // every regime is visited
  CHECK(seen[1] > 300);
  CHECK(seen[2] > 300);
}

TEST_CASE("the exact 2D local solve in each regime, by hand", "[pair-block]") {
  // Wb = I, shift = 0, mubar = 0.5: u = R + c.
  PairBlock<2> b;
  b.Wii = b.Wb = b.M = Eigen::Matrix2d::Identity();
  b.E.setZero();
  b.shift.setZero();
  b.mubar = 0.5;
  b.rho = 1;
  b.prescribed = false;
  Eigen::Vector2d R;
  R.setConstant(7);  // the exact solve does not depend on the start
  CHECK(solve_pair<2>(b, Eigen::Vector2d(0.3, 1.0), R, 100, 1e-12, 0, 0) == Status::Separated);
  CHECK(R.norm() == 0.0);
  CHECK(solve_pair<2>(b, Eigen::Vector2d(0.2, -1.0), R, 100, 1e-12, 0, 0) == Status::Stick);
  CHECK((R - Eigen::Vector2d(-0.2, 1.0)).norm() < 1e-15);
  CHECK(solve_pair<2>(b, Eigen::Vector2d(2.0, -1.0), R, 100, 1e-12, 0, 0) == Status::Slide);
  CHECK((R - Eigen::Vector2d(-0.5, 1.0)).norm() < 1e-15);  // R_t = -mubar R_n, against the slip 1.5
  CHECK(solve_pair<2>(b, Eigen::Vector2d(-2.0, -1.0), R, 100, 1e-12, 0, 0) == Status::Slide);
  CHECK((R - Eigen::Vector2d(0.5, 1.0)).norm() < 1e-15);
}

TEST_CASE("a pair whose spring cancels its flexibility (det(I - W_ii E) = 0) is refused, naming it", "[pair-block]") {
  // Three pairs, W0 diagonal-dominant; pair 1's normal spring E = 1 / W0_nn: nothing holds it.
  Eigen::MatrixXd W(6, 6);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) W(r, c) = r == c ? 2.0 : 0.1;
  const DenseDelassus W0(W);
  ContactProblem pb;
  pb.layout = Layout{2};
  pb.W0 = &W0;
  pb.q0 = pb.Dbeta = pb.u_ref = Eigen::VectorXd::Zero(6);
  pb.Dref = Eigen::VectorXd::Constant(6, 0.1);
  pb.Dref[3] = 1.0 / W(3, 3);
  pb.Dref[2] = 0;
  pb.mubar = pb.g0 = Eigen::VectorXd::Zero(3);
  try {
    make_blocks<2>(pb, RhoRule::Eigen);
    FAIL("the pair was accepted");
  } catch (const SolveError& e) {
    CHECK(e.node == 1);
    CHECK_THAT(e.what(), Catch::Contains("contact node 1 has no stiffness left"));
  }
}

TEST_CASE("The largest eigenvalue of a pair's 2 x 2 and 3 x 3 flexibility in closed form is the iterative one's",
          "[pair-block]") {
  // rho = 1 / lambda_max (docs/MODEL.md s5) from the closed forms (2 x 2: the root; 3 x 3: the
  // characteristic cubic's): against Eigen's iterative solver on random SPD blocks over twelve
  // decades of scale, nearly equal eigenvalues (a pair's isotropic tangential flexibility),
  // strong coupling and a nearly singular block (a held component). The cubic's roots lose
  // digits where two eigenvalues nearly coincide (5e-9 relative at worst here): rho is a step
  // length, and the natural-map residual's scale moves by as little.
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> U(-1, 1), P(0, 1);
  for (int trial = 0; trial < 3000; ++trial) {
    const double scale = std::pow(10.0, -6 + 12 * P(gen));
    const Eigen::Matrix3d B = Eigen::Matrix3d::NullaryExpr([&]() { return U(gen); });
    Eigen::Matrix3d S;
    switch (trial % 4) {
      case 0: S = B * B.transpose() + 0.1 * Eigen::Matrix3d::Identity(); break;
      case 1: S = Eigen::Vector3d(1.0, 1.0 + 1e-9 * P(gen), 0.5 + P(gen)).asDiagonal(); break;
      case 2: S = B * B.transpose() + 1e-9 * Eigen::Matrix3d::Identity(); break;
      default: {
        const Eigen::Matrix3d Q = Eigen::HouseholderQR<Eigen::Matrix3d>(B).householderQ();
        S = Q * Eigen::Vector3d(1.0, 1.0 - 1e-12, 0.3 * P(gen)).asDiagonal() * Q.transpose();
      }
    }
    S = (scale * 0.5 * (S + S.transpose())).eval();
    const double iterative = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(S).eigenvalues().maxCoeff();
    INFO("trial " << trial << ": " << largest_eigenvalue(S) << " against " << iterative);
    REQUIRE(std::abs(largest_eigenvalue(S) - iterative) <= 1e-8 * iterative);
    const Eigen::Matrix2d S2 = S.topLeftCorner<2, 2>();
    const double iterative2 = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(S2).eigenvalues().maxCoeff();
    REQUIRE(std::abs(largest_eigenvalue(S2) - iterative2) <= 1e-12 * iterative2);
  }
}
