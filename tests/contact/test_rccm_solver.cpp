// The classical RCCM solver (PSOR within a fixed point on the sliding threshold,
// docs/solvers/rccm.md): on random condensed problems it satisfies Signorini, Coulomb and the
// condensed equilibrium and finds the bipotential solver's solution; whole B1 and B2 runs with
// it give the bipotential runs' beta and Rbar.
#include "helpers.hpp"
#include "random_problem.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/contact/bipotential_solver.hpp"
#include "rccm/contact/rccm_solver.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <random>

using namespace rccm;
using rccm::testing::Family;
using rccm::testing::RandomProblem;

namespace {


SolverParams params(double omega = 1.5) {
  SolverParams p;
  p.tolerance = 1e-10;
  p.max_iterations = 20000;
  p.over_relaxation = omega;
  return p;
}

/// The solution satisfies the condensed equilibrium and the law, and is the bipotential one.
void require_solution(const ContactProblem& pb, const ContactSolution& s, const ContactSolution& reference) {
  REQUIRE(s.converged);
  REQUIRE(s.residual <= 1e-10);
  testing::require_solution(pb, s);
  REQUIRE(reference.converged);
  REQUIRE((s.Rbar - reference.Rbar).norm() <= 1e-8 * (1 + reference.Rbar.norm()));
  REQUIRE((s.u - reference.u).norm() <= 1e-8 * (1 + reference.u.norm()));
  REQUIRE(s.status == reference.status);
}

}  // namespace

TEST_CASE("rccm: random problems, with and without springs and initial gaps: the law holds, the bipotential "
          "solution",
          "[rccm-solver]") {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> gap(0, 0.5);
  for (bool springs : {false, true})
    for (int trial = 0; trial < 40; ++trial) {
      RandomProblem rp(1 + trial % 8, 2, Family::Mild, springs, gen);
      if (trial % 2) rp.pb.g0 = Eigen::VectorXd::NullaryExpr(rp.pb.size(), [&]() { return gap(gen); });
      const ContactSolution s = RccmSolver(params()).solve(rp.pb, {}, {});
      const ContactSolution reference = BipotentialSolver(params()).solve(rp.pb, {}, {});
      INFO("trial " << trial << " springs " << springs << ": " << s.iterations << " sweeps, residual " << s.residual);
      require_solution(rp.pb, s, reference);
    }
}

TEST_CASE("rccm: over-relaxation 1.0, 1.5 and 1.8 reach the same solution", "[rccm-solver]") {
  std::mt19937 gen(5);
  for (int trial = 0; trial < 12; ++trial) {
    const RandomProblem rp(4 + trial, 2, Family::Mild, true, gen);
    const ContactSolution reference = BipotentialSolver(params()).solve(rp.pb, {}, {});
    for (double omega : {1.0, 1.5, 1.8}) {
      const ContactSolution s = RccmSolver(params(omega)).solve(rp.pb, {}, {});
      INFO("trial " << trial << " omega " << omega << ": " << s.iterations << " sweeps");
      require_solution(rp.pb, s, reference);
    }
  }
}

TEST_CASE("rccm: 3D pairs, the Tresca disk |Rbar_t| <= mubar Rbar_n", "[rccm-solver]") {
  std::mt19937 gen(13);
  for (bool springs : {false, true})
    for (int trial = 0; trial < 16; ++trial) {
      const RandomProblem rp(1 + trial % 6, 3, Family::Mild, springs, gen);
      const ContactSolution s = RccmSolver(params()).solve(rp.pb, {}, {});
      const ContactSolution reference = BipotentialSolver(params()).solve(rp.pb, {}, {});
      INFO("trial " << trial << " springs " << springs << ": " << s.iterations << " sweeps");
      require_solution(rp.pb, s, reference);
    }
}

TEST_CASE("rccm: a single free node in each regime: the friction threshold comes from the fixed point",
          "[rccm-solver]") {
  // One node, W = diag(1, 1), no springs, mubar = 0.5: u = R + q.
  const DenseDelassus W(Eigen::MatrixXd::Identity(2, 2));
  ContactProblem pb;
  pb.W0 = &W;
  pb.mubar = Eigen::VectorXd::Constant(1, 0.5);
  pb.g0 = Eigen::VectorXd::Zero(1);
  pb.u_ref = pb.Dref = pb.Dbeta = Eigen::VectorXd::Zero(2);
  RccmSolver solver(params());
  SECTION("opening: no force") {
    pb.q0 = Eigen::Vector2d(0.3, 1.0);
    const ContactSolution s = solver.solve(pb, {}, {});
    REQUIRE(s.converged);
    CHECK(s.Rbar.norm() == 0.0);
    CHECK(s.status[0] == Status::Separated);
  }
  SECTION("pressed, small shear: stick, R = -q") {
    pb.q0 = Eigen::Vector2d(0.2, -1.0);
    const ContactSolution s = solver.solve(pb, {}, {});
    REQUIRE(s.converged);
    CHECK((s.Rbar - Eigen::Vector2d(-0.2, 1.0)).norm() < 1e-10);
    CHECK(s.status[0] == Status::Stick);
  }
  SECTION("pressed, large shear: slide with R_t = -mubar R_n, after more than one Tresca problem") {
    pb.q0 = Eigen::Vector2d(2.0, -1.0);
    const ContactSolution s = solver.solve(pb, {}, {});
    REQUIRE(s.converged);
    CHECK(s.Rbar[1] == Approx(1.0).epsilon(1e-10));
    CHECK(s.Rbar[0] == Approx(-0.5).epsilon(1e-10));
    CHECK(s.u[0] == Approx(1.5).epsilon(1e-10));  // slip = q_t + R_t
    CHECK(s.status[0] == Status::Slide);
    // From zero the first threshold is 0 (frictionless); the second is mubar R_n.
    CHECK(s.iterations >= 2);
  }
}

TEST_CASE("rccm: warm-started from its solution, one sweep confirms it", "[rccm-solver]") {
  std::mt19937 gen(11);
  for (int trial = 0; trial < 8; ++trial) {
    const RandomProblem rp(6 + trial, 2, Family::Mild, true, gen);
    RccmSolver solver(params());
    const ContactSolution cold = solver.solve(rp.pb, {}, {});
    REQUIRE(cold.converged);
    const ContactSolution warm = solver.solve(rp.pb, cold.Rbar, cold.u);
    INFO("trial " << trial << ": cold " << cold.iterations << " sweeps");
    REQUIRE(warm.converged);
    CHECK(warm.iterations == 1);
    CHECK((warm.Rbar - cold.Rbar).norm() <= 1e-9 * (1 + cold.Rbar.norm()));
  }
}

namespace {

/// A config run whole with each contact solver: per snapshot, the largest difference of beta
/// and of Rbar (relative to the largest |Rbar| of the bipotential run), and the contact
/// iterations per solve of each.
struct Agreement {
  std::vector<double> t, beta, Rbar;
  double sweeps_rccm = 0, sweeps_bipotential = 0;
};

Agreement compare_runs(const std::string& file) {
  const auto run = [&](const char* method) {
    return Simulation(load_config(test::shipped(file), {"integrator.method=euler", std::string("solver.method=") + method}))
        .run();
  };
  const RunResult b = run("bipotential"), r = run("rccm");
  REQUIRE(b.stopped.empty());
  REQUIRE(r.stopped.empty());
  REQUIRE(r.snapshots.size() == b.snapshots.size());
  Agreement a;
  for (std::size_t k = 0; k < b.snapshots.size(); ++k) {
    const Snapshot &x = r.snapshots[k], &ref = b.snapshots[k];
    a.t.push_back(ref.t);
    a.beta.push_back((x.beta - ref.beta).cwiseAbs().maxCoeff());
    a.Rbar.push_back((x.Rbar - ref.Rbar).cwiseAbs().maxCoeff() / ref.Rbar.cwiseAbs().maxCoeff());
  }
  a.sweeps_rccm = double(r.solves.sweeps) / double(r.solves.contact_solves);
  a.sweeps_bipotential = double(b.solves.sweeps) / double(b.solves.contact_solves);
  return a;
}

}  // namespace

// The paper's explicit Euler with its 210 steps: both runs take the same steps, so the runs
// differ by what the contact solves leave within the tolerance (1e-10), carried by beta.
TEST_CASE("rccm: B1 with Euler's 210 steps gives the bipotential run's beta and Rbar", "[rccm-solver]") {
  const Agreement a = compare_runs("b1.cfg");
  for (std::size_t k = 0; k < a.t.size(); ++k) {
    INFO("t = " << a.t[k] << ": max |beta diff| " << a.beta[k] << ", max |Rbar diff| / max |Rbar| " << a.Rbar[k]);
    CHECK(a.beta[k] <= 1e-8);
    CHECK(a.Rbar[k] <= 5e-8);
  }
  INFO("sweeps per solve: rccm " << a.sweeps_rccm << ", bipotential " << a.sweeps_bipotential);
  CHECK(a.sweeps_rccm > 10 * a.sweeps_bipotential);  // no exact step: PSOR crawls through the layer
}

TEST_CASE("rccm: B2 with Euler's 210 steps gives the bipotential run's beta and Rbar", "[rccm-solver]") {
  const Agreement a = compare_runs("b2.cfg");
  for (std::size_t k = 0; k < a.t.size(); ++k) {
    INFO("t = " << a.t[k] << ": max |beta diff| " << a.beta[k] << ", max |Rbar diff| / max |Rbar| " << a.Rbar[k]);
    // Up to the paper's t3 Euler is stable on B2; past it dt (Cn u_n^2 + Ct u_t^2) / alpha
    // reaches 31, and each step multiplies a difference of beta by up to 30.
    const bool stable = a.t[k] <= 3.6;
    CHECK(a.beta[k] <= (stable ? 1e-10 : 2e-6));
    CHECK(a.Rbar[k] <= (stable ? 5e-9 : 5e-7));
  }
  INFO("sweeps per solve: rccm " << a.sweeps_rccm << ", bipotential " << a.sweeps_bipotential);
  CHECK(a.sweeps_rccm > 10 * a.sweeps_bipotential);
}
