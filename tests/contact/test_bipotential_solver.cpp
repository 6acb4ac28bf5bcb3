// The bipotential solver on random condensed problems: Signorini and Coulomb residuals,
// Gauss-Seidel and Jacobi forms agree, the spring folded into the local solve.
#include "rccm/contact/bipotential_solver.hpp"

#include "random_problem.hpp"
#include "rccm/contact/solver_tuning.hpp"
#include "rccm/la/blas_threads.hpp"
#include "rccm/la/hodlr.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace rccm;
using rccm::testing::Family;
using rccm::testing::RandomProblem;

namespace {


SolverParams params(SweepForm form, bool active_set) {
  SolverParams p;
  p.tolerance = 1e-10;
  p.max_iterations = 20000;
  p.form = form;
  p.active_set = active_set;
  return p;
}

/// The reference: Gauss-Seidel sweeps alone, neither exact steps nor Anderson's extrapolation.
SolverParams plain_sweeps() {
  SolverParams p = params(SweepForm::GaussSeidel, false);
  p.anderson = 0;
  return p;
}

}  // namespace

TEST_CASE("random problems: Signorini and Coulomb hold, both forms agree", "[solver]") {
  std::mt19937 gen(7);
  for (bool springs : {false, true})
    for (int trial = 0; trial < 40; ++trial) {
      const RandomProblem rp(1 + trial % 8, 2, Family::Mild, springs, gen);
      const ContactSolution gs = BipotentialSolver(params(SweepForm::GaussSeidel, true)).solve(rp.pb, {}, {});
      const ContactSolution gs_plain = BipotentialSolver(plain_sweeps()).solve(rp.pb, {}, {});
      const ContactSolution ja = BipotentialSolver(params(SweepForm::Jacobi, false)).solve(rp.pb, {}, {});
      INFO("trial " << trial << " springs " << springs);
      REQUIRE(gs.converged);
      INFO("plain GS: sweeps " << gs_plain.iterations << " residual " << gs_plain.residual << " worst " << gs_plain.worst_node << " mubar " << rp.pb.mubar.transpose());
      REQUIRE(gs_plain.converged);
      REQUIRE(ja.converged);
      for (const ContactSolution* s : {&gs, &gs_plain, &ja}) {
        // The solution is consistent with the condensed equations ...
        const Eigen::VectorXd y = s->Rbar + (rp.pb.Dref - rp.pb.Dbeta).cwiseProduct(s->u);
        REQUIRE((rp.matrix() * y + rp.pb.q0 - s->u).norm() <= 1e-10 * (1 + s->u.norm()));
        // ... and with the law.
        const ContactResiduals r = residuals(rp.pb, *s);
        INFO("pen " << r.penetration << " ten " << r.tension << " comp " << r.complementarity << " coul "
                    << r.coulomb << " stick " << r.stick_slip << " dir " << r.slip_direction);
        REQUIRE(r.max() <= 1e-8);
      }
      const double scale = 1 + gs.Rbar.norm();
      REQUIRE((gs.Rbar - ja.Rbar).norm() <= 1e-8 * scale);
      REQUIRE((gs.Rbar - gs_plain.Rbar).norm() <= 1e-8 * scale);
    }
}

TEST_CASE("warm starts: the exact-first step follows a drifting problem as plain Gauss-Seidel does", "[solver]") {
  // A sequence of nearby problems (load, beta and friction drifting, as between the stages
  // of the integrator), each started from the previous solution with one solver object that
  // keeps its factorization, against cold plain Gauss-Seidel.
  std::mt19937 gen(11);
  for (int trial = 0; trial < 12; ++trial) {
    RandomProblem rp(4 + trial, 2, Family::Mild, true, gen);
    BipotentialSolver warm(params(SweepForm::GaussSeidel, true));
    ContactSolution previous = warm.solve(rp.pb, {}, {});
    REQUIRE(previous.converged);
    int exact_solves = 0, sweeps = 0;
    for (int step = 0; step < 20; ++step) {
      rccm::testing::drift(rp.pb, 0.5, gen);
      const ContactSolution s = warm.solve(rp.pb, previous.Rbar, previous.u);
      const ContactSolution reference = BipotentialSolver(plain_sweeps()).solve(rp.pb, {}, {});
      INFO("trial " << trial << " step " << step);
      REQUIRE(s.converged);
      REQUIRE(reference.converged);
      const Eigen::VectorXd y = s.Rbar + (rp.pb.Dref - rp.pb.Dbeta).cwiseProduct(s.u);
      REQUIRE((rp.matrix() * y + rp.pb.q0 - s.u).norm() <= 1e-10 * (1 + s.u.norm()));
      REQUIRE(residuals(rp.pb, s).max() <= 1e-8);
      REQUIRE((s.Rbar - reference.Rbar).norm() <= 1e-8 * (1 + reference.Rbar.norm()));
      exact_solves += s.exact_solves;
      sweeps += s.iterations;
      previous = s;
    }
    // Warm: a verifying pass, an exact step and a second pass, rarely more.
    INFO("trial " << trial << ": " << sweeps << " passes and sweeps, " << exact_solves << " exact solves in 20 solves");
    CHECK(sweeps <= 20 * 3);
  }
}

TEST_CASE("3D warm starts: exact steps with turning slip directions agree with plain Gauss-Seidel, dense and compressed W0",
          "[solver]") {
  // As above with 3D pairs (slip directions on the circle, most pairs sliding in the hard
  // family), on the dense W0 and on the same W0 compressed (la/hodlr.hpp, leaves of 4 pairs):
  // the exact step's slide rows fix a direction, whose turn the refinement absorbs.
  std::mt19937 gen(19);
  for (int trial = 0; trial < 8; ++trial) {
    RandomProblem rp(12 + 3 * trial, 3, trial % 2 ? Family::Hard : Family::Mild, true, gen);
    const CompressedDelassus compressed{HodlrMatrix(rp.matrix(), 1e-14 * rp.matrix().diagonal().maxCoeff(), 12, 3)};
    for (const DelassusOperator* W0 : {static_cast<const DelassusOperator*>(&rp.W), static_cast<const DelassusOperator*>(&compressed)}) {
      ContactProblem pb = rp.pb;
      pb.W0 = W0;
      BipotentialSolver warm(params(SweepForm::GaussSeidel, true));
      ContactSolution previous = warm.solve(pb, {}, {});
      REQUIRE(previous.converged);
      int exact_solves = 0;
      for (int step = 0; step < 12; ++step) {
        rccm::testing::drift(pb, 1.0, gen);
        const ContactSolution s = warm.solve(pb, previous.Rbar, previous.u);
        const ContactSolution reference = BipotentialSolver(plain_sweeps()).solve(pb, {}, {});
        INFO("trial " << trial << (W0 == &compressed ? " compressed" : " dense") << " step " << step);
        REQUIRE(s.converged);
        REQUIRE(reference.converged);
        rccm::testing::require_solution(pb, s);
        REQUIRE((s.Rbar - reference.Rbar).norm() <= 1e-8 * (1 + reference.Rbar.norm()));
        exact_solves += s.exact_solves;
        previous = s;
      }
      if (W0 == &rp.W) CHECK(exact_solves > 0);  // the dense path takes exact steps from a warm start
    }
  }
}

TEST_CASE("Anderson-accelerated sweeps solve what plain sweeps solve, in fewer sweeps: 2D and 3D, dense and compressed W0",
          "[solver]") {
  // Sweeps alone (no exact step), extrapolated from the last 5 (solver.anderson, the
  // default) against the plain sweeps, on the hard family (most pairs sliding, every pair
  // coupled to every other: where the plain sweeps are slow) and the mild one.
  std::mt19937 gen(23);
  long sweeps_plain = 0, sweeps_mixed = 0;
  for (int dim : {2, 3})
    for (int trial = 0; trial < 8; ++trial) {
      RandomProblem rp(10 + 4 * trial, dim, trial % 4 ? Family::Hard : Family::Mild, trial % 2 == 1, gen);
      const CompressedDelassus compressed{HodlrMatrix(rp.matrix(), 1e-14 * rp.matrix().diagonal().maxCoeff(), 4 * dim, dim)};
      for (const DelassusOperator* W0 : {static_cast<const DelassusOperator*>(&rp.W), static_cast<const DelassusOperator*>(&compressed)}) {
        ContactProblem pb = rp.pb;
        pb.W0 = W0;
        SolverParams accelerated = plain_sweeps();
        accelerated.anderson = 5;
        const ContactSolution mixed = BipotentialSolver(accelerated).solve(pb, {}, {});
        const ContactSolution plain = BipotentialSolver(plain_sweeps()).solve(pb, {}, {});
        INFO("dim " << dim << " trial " << trial << (W0 == &compressed ? " compressed" : " dense") << ": sweeps "
                    << mixed.iterations << " mixed, " << plain.iterations << " plain");
        REQUIRE(mixed.converged);
        REQUIRE(plain.converged);
        rccm::testing::require_solution(pb, mixed);
        REQUIRE((mixed.Rbar - plain.Rbar).norm() <= 1e-8 * (1 + plain.Rbar.norm()));
        sweeps_plain += plain.iterations;
        sweeps_mixed += mixed.iterations;
      }
    }
  INFO("sweeps in all: " << sweeps_mixed << " mixed, " << sweeps_plain << " plain");
  CHECK(3 * sweeps_mixed < 2 * sweeps_plain);  // 558 against 938 when written
}

TEST_CASE("block sweeps solve what single sweeps solve in fewer sweeps where W0 couples neighbours on a 3D surface",
          "[solver]") {
  // Pairs on a grid of a surface, W0 coupling them by a kernel that decays with their distance
  // (as an interface's flexibility does), listed row by row: runs of consecutive pairs are
  // neighbours. Pressed into contact with a random shear (most pairs slide, some stick), no
  // springs. On 16 x 16 pairs (768 rows: two blocks of 400 rows at most), each run of pairs
  // swept twice or three times per sweep (solver.block_sweeps) must reach the solution of
  // plain sweeps, dense and compressed, in fewer sweeps; on 8 x 8 (192 rows, one block) the
  // sweeps are the plain ones.
  for (int side : {16, 8}) {
    const int n = side * side, m = 3 * n;
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(m, m);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double k = 1.0 / (1.0 + std::hypot(i % side - j % side, i / side - j / side));
        for (int a = 0; a < 3; ++a) W(3 * i + a, 3 * j + a) = (a == 2 ? 1.0 : 0.7) * k;
      }
    W.diagonal().array() += 0.5;
    std::mt19937 gen(31);
    std::uniform_real_distribution<double> U(-1, 1);
    const DenseDelassus dense{W};
    const CompressedDelassus compressed{
        HodlrMatrix::symmetric(m, [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(W * X); }, 1e-13, 48, 3)};
    ContactProblem pb;
    pb.layout.dim = 3;
    pb.q0 = Eigen::VectorXd::NullaryExpr(m, [&]() { return U(gen); });
    for (int i = 0; i < n; ++i) pb.q0[3 * i + 2] -= 1.0;  // pressed into contact
    pb.mubar = Eigen::VectorXd::Constant(n, 0.3);
    pb.g0 = Eigen::VectorXd::Zero(n);
    pb.u_ref = Eigen::VectorXd::Zero(m);
    pb.Dref = pb.Dbeta = Eigen::VectorXd::Zero(m);
    for (const DelassusOperator* W0 : {static_cast<const DelassusOperator*>(&dense), static_cast<const DelassusOperator*>(&compressed)}) {
      pb.W0 = W0;
      SolverParams p = params(SweepForm::GaussSeidel, false);
      const ContactSolution single = BipotentialSolver(p).solve(pb, {}, {});
      REQUIRE(single.converged);
      rccm::testing::require_solution(pb, single);
      for (int block_sweeps : {2, 3}) {
        p.block_sweeps = block_sweeps;
        const ContactSolution s = BipotentialSolver(p).solve(pb, {}, {});
        INFO(side << " x " << side << (W0 == &dense ? " dense" : " compressed") << ", block sweeps " << block_sweeps << ": "
                  << s.iterations << " sweeps against " << single.iterations);
        REQUIRE(s.converged);
        rccm::testing::require_solution(pb, s);
        CHECK((s.Rbar - single.Rbar).norm() <= 1e-8 * (1 + single.Rbar.norm()));
        if (m > tuning::sweep_block_rows)
          CHECK(s.iterations < single.iterations);
        else
          CHECK(s.iterations == single.iterations);
      }
    }
  }
}

TEST_CASE("the exact step's rows: a slide direction that turned a little keeps its factorized rows", "[solver]") {
  const auto slide = [](double angle) {
    PairRows r;
    r.status = Status::Slide;
    r.direction = Eigen::Vector2d(std::cos(angle), std::sin(angle));
    return r;
  };
  const double drift = tuning::slide_direction_drift;
  CHECK(slide(0.3) == slide(0.3 + 0.5 * drift));  // |d - d'| = 2 sin(angle / 2) ~ angle
  CHECK(slide(0.3) != slide(0.3 + 2 * drift));
  CHECK(slide(1.0) != slide(1.0 + 3.14159));       // reversed
  PairRows stick = slide(0.3);
  stick.status = Status::Stick;
  CHECK(stick != slide(0.3));
  stick.direction = Eigen::Vector2d(0.9, 0.1);      // not sliding: the direction does not count
  PairRows other = stick;
  other.direction = Eigen::Vector2d(-1, 0);
  CHECK(stick == other);
  // 2D: directions +-1 along t.
  PairRows left = slide(0.0), right = left;
  right.direction = {-1, 0};
  CHECK(left != right);
}

TEST_CASE("a single free node is solved exactly in each regime", "[solver]") {
  // One node, W = diag(1, 1), no springs, mubar = 0.5: u = R + q.
  const DenseDelassus W(Eigen::MatrixXd::Identity(2, 2));
  ContactProblem pb;
  pb.W0 = &W;
  pb.mubar = Eigen::VectorXd::Constant(1, 0.5);
  pb.g0 = Eigen::VectorXd::Zero(1);
  pb.u_ref = pb.Dref = pb.Dbeta = Eigen::VectorXd::Zero(2);
  BipotentialSolver solver(params(SweepForm::GaussSeidel, true));
  SECTION("opening: no force") {
    pb.q0 = Eigen::Vector2d(0.3, 1.0);
    const ContactSolution s = solver.solve(pb, {}, {});
    CHECK(s.Rbar.norm() < 1e-14);
    CHECK(s.status[0] == Status::Separated);
  }
  SECTION("pressed, small shear: stick, R = -q") {
    pb.q0 = Eigen::Vector2d(0.2, -1.0);
    const ContactSolution s = solver.solve(pb, {}, {});
    CHECK((s.Rbar - Eigen::Vector2d(-0.2, 1.0)).norm() < 1e-12);
    CHECK(s.status[0] == Status::Stick);
  }
  SECTION("pressed, large shear: slide with R_t = -mubar R_n") {
    pb.q0 = Eigen::Vector2d(2.0, -1.0);
    const ContactSolution s = solver.solve(pb, {}, {});
    CHECK(s.Rbar[1] == Approx(1.0));
    CHECK(s.Rbar[0] == Approx(-0.5));
    CHECK(s.u[0] == Approx(1.5));  // slip = q_t + R_t
    CHECK(s.status[0] == Status::Slide);
  }
}

TEST_CASE("a cold solve that one sweep solves stops after it: uncoupled pairs in every regime", "[solver]") {
  // W block-diagonal (each pair alone): one Gauss-Seidel sweep solves each pair exactly. From
  // nothing, the first sweep's change of Rbar is the whole solution and says nothing; the
  // verifying pass after it finds the residual below the tolerance, and no second sweep runs
  // (Siconos' NSGS stops after one iteration alike).
  Eigen::MatrixXd Wd = Eigen::MatrixXd::Zero(8, 8);
  for (int i = 0; i < 4; ++i) Wd.block<2, 2>(2 * i, 2 * i) << 1.0 + 0.1 * i, 0.2, 0.2, 2.0 - 0.1 * i;
  const DenseDelassus W(Wd);
  ContactProblem pb;
  pb.W0 = &W;
  pb.mubar = Eigen::VectorXd::Constant(4, 0.5);
  pb.g0 = Eigen::VectorXd::Zero(4);
  pb.u_ref = pb.Dref = pb.Dbeta = Eigen::VectorXd::Zero(8);
  pb.q0.resize(8);
  pb.q0 << 0.3, 1.0,   // opening
      0.1, -1.0,       // pressed, small shear: stick
      3.0, -1.0,       // pressed, large shear: slide
      -2.5, -0.5;      // slide the other way
  for (const bool active_set : {false, true}) {
    INFO("active_set " << active_set);
    const ContactSolution s = BipotentialSolver(params(SweepForm::GaussSeidel, active_set)).solve(pb, {}, {});
    REQUIRE(s.converged);
    CHECK(s.iterations == 1);
    CHECK(s.residual <= 1e-10);
    CHECK(residuals(pb, s).max() <= 1e-10);
    CHECK(s.status[0] == Status::Separated);
    CHECK(s.status[1] == Status::Stick);
    CHECK(s.status[2] == Status::Slide);
    CHECK(s.status[3] == Status::Slide);
  }
}

TEST_CASE("a solver reused along a sequence of problems (cached active-set factorization) gives fresh solutions",
          "[solver]") {
  // Like the stages of a time step: the same W0, beta and the load drifting, so the status
  // pattern repeats or changes at a few nodes (low-rank update) or many (new factorization).
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> U(-1, 1);
  RandomProblem rp(12, 2, Family::Mild, true, gen);
  BipotentialSolver reused(params(SweepForm::GaussSeidel, true));
  ContactSolution previous;
  for (int k = 0; k < 60; ++k) {
    for (int i = 0; i < rp.pb.size(); ++i) {
      const double beta = std::sqrt(rp.pb.Dbeta[2 * i] / rp.pb.Dref[2 * i]);
      const double next = std::clamp(beta * (1 - 0.05 * std::abs(U(gen))), 0.0, 1.0);
      rp.pb.Dbeta.segment<2>(2 * i) = next * next * rp.pb.Dref.segment<2>(2 * i);
      rp.pb.mubar[i] = 0.4 * (1 - next);
    }
    rp.pb.q0 += 0.1 * Eigen::VectorXd::NullaryExpr(rp.pb.q0.size(), [&]() { return U(gen); });
    const ContactSolution warm = reused.solve(rp.pb, previous.Rbar, previous.u);
    const ContactSolution fresh = BipotentialSolver(params(SweepForm::GaussSeidel, true)).solve(rp.pb, {}, {});
    INFO("problem " << k);
    REQUIRE(warm.converged);
    REQUIRE(residuals(rp.pb, warm).max() <= 1e-8);
    REQUIRE((warm.Rbar - fresh.Rbar).norm() <= 1e-8 * (1 + fresh.Rbar.norm()));
    previous = warm;
  }
}

TEST_CASE("slowly converging sweeps: a small change of Rbar is not convergence, the residual decides", "[solver]") {
  // Ill-conditioned problems (W's spectrum shifted down to a condition number ~ 1e4, most
  // pairs sliding) solved by sweeps alone: a sweep changes Rbar by far less than the error
  // left, so a solve that stopped on the change would leave residuals of 1e-8 and more.
  std::mt19937 gen(31);
  for (int trial = 0; trial < 12; ++trial) {
    RandomProblem rp(12 + trial, 2, Family::Hard, trial % 2 == 1, gen);
    Eigen::MatrixXd W = rp.matrix();
    W.diagonal().array() -= 0.0099;
    rp.W = DenseDelassus(W);
    rp.pb.W0 = &rp.W;
    SolverParams p = params(SweepForm::GaussSeidel, false);
    p.max_iterations = 200000;
    const ContactSolution s = BipotentialSolver(p).solve(rp.pb, {}, {});
    INFO("trial " << trial << ": " << s.iterations << " sweeps, residual " << s.residual);
    REQUIRE(s.converged);
    CHECK(s.residual <= p.tolerance);
    const ContactResiduals r = residuals(rp.pb, s);
    INFO("pen " << r.penetration << " ten " << r.tension << " comp " << r.complementarity << " coul " << r.coulomb
                << " stick " << r.stick_slip << " dir " << r.slip_direction);
    CHECK(r.max() <= 1e-9);
  }
}

TEST_CASE("a solve stopped by solver.max_iterations leaves a consistent state for its failure message", "[solver]") {
  // The residual and worst pair a failure names are those of the returned state: after the
  // last sweep's extrapolation (solver.anderson) too, u = W0 y + q0 and Rbar = y - E u.
  std::mt19937 gen(29);
  for (int dim : {2, 3})
    for (int trial = 0; trial < 6; ++trial) {
      const RandomProblem rp(20 + trial, dim, Family::Hard, trial % 2 == 1, gen);
      SolverParams p = plain_sweeps();
      p.anderson = 5;
      p.max_iterations = 4;
      const ContactSolution s = BipotentialSolver(p).solve(rp.pb, {}, {});
      INFO("dim " << dim << " trial " << trial << ": residual " << s.residual);
      REQUIRE_FALSE(s.converged);
      CHECK(s.residual > p.tolerance);
      CHECK(s.worst_node >= 0);
      const Eigen::VectorXd E = rp.pb.Dref - rp.pb.Dbeta;
      CHECK((rp.matrix() * s.y + rp.pb.q0 - s.u).norm() <= 1e-10 * (1 + s.u.norm()));
      CHECK((s.y - E.cwiseProduct(s.u) - s.Rbar).norm() <= 1e-12 * (1 + s.y.norm()));
    }
}

TEST_CASE("a singular W (two contacts at one point, Siconos' FC2D_SliderCrankLagrangian00000): the sweeps stay finite",
          "[solver]") {
  // Siconos' slider-crank problem (numerics/src/FrictionContact/test/data/), its (n, t) pairs
  // written here as ours (t, n): the two contacts share their normal rows, W is singular, and
  // the sweeps stagnate at round-off. They used to turn to NaN there (Anderson's mix of zero
  // differences); now they stop unconverged with finite numbers, or converge.
  Eigen::MatrixXd W(4, 4);
  W << 2.365081445699369169233250e+02, -4.642662921766745967033785e+02, 2.365081445699369169233250e+02,
      4.616596337492514976474922e+02,  //
      -4.642665883420582986218506e+02, 9.365610022253570150496671e+02, -4.642665883420582986218506e+02,
      -9.152908496264951736520743e+02,  //
      2.365081445699369169233250e+02, -4.642662921766745967033785e+02, 2.365081445699369169233250e+02,
      4.616596337492514976474922e+02,  //
      4.616593375838677957290201e+02, -9.152908496264951736520743e+02, 4.616593375838677957290201e+02,
      9.365610022253570150496671e+02;
  Eigen::VectorXd q(4), mu(2);
  q << -8.407368208001527065675873e+00, -1.179087309965789476251530e+00, -8.407368208001527065675873e+00,
      -1.179087309965789476251530e+00;
  mu << 0.01, 0.01;
  const PlainContactProblem plain{2, std::make_shared<DenseDelassus>(W), q, mu};
  const ContactProblem pb = from_plain(plain);  // points into `plain`
  SolverParams p = params(SweepForm::GaussSeidel, true);
  p.max_iterations = 300;  // past the 200 Anderson sweeps
  const ContactSolution s = BipotentialSolver(p).solve(pb, {}, {});
  INFO("sweeps " << s.iterations << " residual " << s.residual);
  REQUIRE(s.Rbar.allFinite());
  REQUIRE(s.u.allFinite());
  REQUIRE(std::isfinite(s.residual));
  // Whether converged or not, the contacts push (Signorini) and the normal rows close.
  CHECK(s.Rbar[1] > 0);
  CHECK(s.Rbar[3] > 0);
  CHECK(std::abs(s.u[1]) <= 1e-6 * std::abs(q[1]));
}

TEST_CASE("the sweeps' tolerance is relative to the largest force, the adhesive ones included", "[solver]") {
  // Pair 0 is held open by its spring (u_n = 1 mm, Radh_n = -1e6 N); pairs 1 and 2 touch with
  // reactions of 5e-7 N, coupled through W0 (c = 0.7: plain sweeps contract by c^2 = 0.49).
  // The verifying pass scales a pair's residual by at least tuning::residual_level_floor (1e-8)
  // of the largest force, 1e6 N, adhesive included: the reactions are settled once their error
  // is below 1e-10 x 1e-2 N, log(1e-12 / 5e-7) / log(0.49) = 18.4 sweeps from zero. Scaled by
  // the largest reaction alone (5e-7 N) they would need 1e-10 of their own size: 32 sweeps.
  Eigen::MatrixXd W = Eigen::MatrixXd::Identity(6, 6);
  W(3, 5) = W(5, 3) = 0.7;
  const DenseDelassus W0(W);
  ContactProblem pb;
  pb.layout = Layout{2};
  pb.W0 = &W0;
  pb.q0 = Eigen::VectorXd::Zero(6);
  pb.q0 << 0, 1.0, 0, -8.5e-7, 0, -8.5e-7;
  pb.Dref = pb.Dbeta = Eigen::VectorXd::Constant(6, 1e6);  // beta = 1: E = 0, the springs in W0
  pb.u_ref = Eigen::VectorXd::Zero(6);
  pb.mubar = pb.g0 = Eigen::VectorXd::Zero(3);
  SolverParams p = plain_sweeps();
  p.max_iterations = 1000;
  const ContactSolution s = BipotentialSolver(p).solve(pb, {}, {});
  INFO("sweeps " << s.iterations << ", Rbar " << s.Rbar.transpose());
  REQUIRE(s.converged);
  CHECK(s.Rbar[1] == 0.0);
  CHECK(std::abs(s.Rbar[3] - 5e-7) <= 1e-10);  // the tolerance's 1e-12 N, over 1 - c^2 and a sweep
  CHECK(std::abs(s.Rbar[5] - 5e-7) <= 1e-10);
  CHECK(s.iterations >= 17);
  CHECK(s.iterations <= 20);
}

TEST_CASE("A compressed W0's sweeps are counted and so are those several threads shared", "[solver]") {
  // Every sweep of a compressed W0 is timed (la/thread_choice.hpp): a cold solve's iterations
  // are all sweeps; the first ten of a new solver take the threads there are, the next ten
  // (the first probe) one; a dense W0's sweeps are not timed.
  std::mt19937 gen(5);
  RandomProblem rp(40, 3, Family::Hard, false, gen);
  const CompressedDelassus compressed{HodlrMatrix(rp.matrix(), 1e-14 * rp.matrix().diagonal().maxCoeff(), 12, 3)};
  ContactProblem pb = rp.pb;
  pb.W0 = &compressed;
  const ContactSolution s = BipotentialSolver(plain_sweeps()).solve(pb, {}, {});
  REQUIRE(s.converged);
  INFO(s.iterations << " sweeps, " << s.threaded_sweeps << " in " << blas_threads::most_products() << " threads");
  CHECK(s.timed_sweeps == s.iterations);
  REQUIRE(s.iterations > 10);  // the hard family: the probe comes
  if (blas_threads::most_products() > 1) {
    CHECK(s.threaded_sweeps >= 10);
    CHECK(s.threaded_sweeps <= s.iterations - std::min(s.iterations - 10, 10));
  } else {
    CHECK(s.threaded_sweeps == 0);
  }
  CHECK(s.threaded_sweeps <= s.timed_sweeps);
  const ContactSolution d = BipotentialSolver(plain_sweeps()).solve(rp.pb, {}, {});
  CHECK(d.timed_sweeps == 0);
  CHECK(d.threaded_sweeps == 0);
}
