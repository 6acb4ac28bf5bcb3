// A support on a contact node (B1 held at its right end, u_x = 0 along x = 50 mm, its bottom
// corner a contact node): that pair's slip is prescribed, W0's row for it is zero, and the law
// holds for any tangential Rbar there. The exact step and Newton take the row Rbar_t = 0 (the
// support carries the rest; PairBlock::held) instead of the singular "no slip" row: the
// bipotential, Newton and rccm runs agree, the solves take a few sweeps (before: 14 per solve
// and up to 42 with ARKODE; the rate-independent limit stalled at its second step).
#include "helpers.hpp"
#include "random_problem.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/contact/bipotential_solver.hpp"
#include "rccm/io/config_reader.hpp"
#include "rccm/model/model.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace rccm;
using namespace rccm::testing;

namespace {

const std::string held_right =
    "loads=({node_set=\"right\";type=\"displacement\";component=\"x\";value=0.0;},"
    "{node_set=\"top_left\";type=\"displacement\";component=\"y\";value=0.3;})";

RunResult run_b1_held(const std::string& method, const std::vector<std::string>& more = {}) {
  std::vector<std::string> o = {held_right, "solver.method=" + method};
  o.insert(o.end(), more.begin(), more.end());
  return Simulation(load_config(test::shipped("b1.cfg"), o)).run();
}

}  // namespace

TEST_CASE("a support on a contact node: the exact step takes its prescribed slip and the three solvers agree",
          "[held]") {
  const Config cfg = load_config(test::shipped("b1.cfg"), {held_right});
  const Model model = test::make_model(cfg);
  int held = -1;  // the pair at the held corner (50, 0)
  for (int i = 0; i < model.interface().size(); ++i)
    if (std::abs(model.mesh().nodes[model.interface().pairs[i].node][0] - 50.0) < 1e-9) held = i;
  REQUIRE(held >= 0);

  const RunResult bip = run_b1_held("bipotential", {"integrator.method=euler"});
  const RunResult newton = run_b1_held("newton", {"integrator.method=euler"});
  const RunResult rccm = run_b1_held("rccm", {"integrator.method=euler"});
  for (const RunResult* r : {&bip, &newton, &rccm}) REQUIRE(r->stopped.empty());
  INFO("sweeps per solve: bipotential " << bip.solves.sweeps_per_solve() << " (max " << bip.solves.max_sweeps
                                        << "), newton " << newton.solves.sweeps_per_solve() << ", rccm "
                                        << rccm.solves.sweeps_per_solve());
  CHECK(bip.solves.max_sweeps <= 6);  // the exact step, not sweeps through the bonded layer
  CHECK(newton.solves.sweeps_per_solve() < 1.5);
  REQUIRE(bip.snapshots.size() == 3);
  for (std::size_t k = 0; k < bip.snapshots.size(); ++k) {
    const Snapshot& b = bip.snapshots[k];
    INFO("t = " << b.t);
    CHECK(b.u[2 * held] == 0.0);  // its slip is the support's
    CHECK(b.Rbar[2 * held] == 0.0);
    CHECK(newton.snapshots[k].Rbar[2 * held] == 0.0);
    CHECK(b.beta.minCoeff() < (k == 0 ? 1.0 : 0.5));  // debonding under way: the springs matter
    for (const Snapshot* other : {&newton.snapshots[k], &rccm.snapshots[k]}) {
      CHECK((other->beta - b.beta).cwiseAbs().maxCoeff() <= 1e-8);
      CHECK((other->u - b.u).cwiseAbs().maxCoeff() <= 1e-8 * b.u.cwiseAbs().maxCoeff());
      // rccm's Rbar_t there is its own member of the law's solution set: compared elsewhere.
      Eigen::VectorXd d = other->Rbar - b.Rbar;
      d[2 * held] = 0.0;
      CHECK(d.cwiseAbs().maxCoeff() <= 5e-8 * b.Rbar.cwiseAbs().maxCoeff());
    }
  }
  // The rate-independent limit (alpha = 0) runs to the end with the exact step.
  const RunResult limit = run_b1_held("bipotential", {"interface.alpha=0"});
  CHECK(limit.stopped.empty());
  CHECK(limit.solves.max_sweeps <= 6);
}

TEST_CASE("the exact step on a pair with a prescribed slip: Rbar_t = 0 there, the law and equilibrium elsewhere",
          "[held]") {
  // Random problems whose pair 2 has its tangential row and column of W0 zero (a support
  // holds its slip at u_ref,t = 0.07 mm since the last step). Warm-started from the solution
  // before a drift of the loads, with Rbar_t = 0.01 there, the exact step must set it to 0 (its row Rbar_t = 0, right-hand side 0) and leave
  // the other pairs as plain sweeps find them.
  std::mt19937 gen(5);
  int stuck = 0;  // trials where pair 2 sticks under pressure: the held row at work
  for (int trial = 0; trial < 20; ++trial) {
    RandomProblem rp(6, 2, Family::Mild, true, gen);
    const Eigen::Index c = rp.pb.layout.offset(2);
    Eigen::MatrixXd W = rp.matrix();
    W.row(c).setZero();
    W.col(c).setZero();
    rp.W = DenseDelassus(W);
    rp.pb.q0[c] = rp.pb.u_ref[c] = 0.07;
    SolverParams exact;
    exact.tolerance = 1e-10;
    exact.max_iterations = 20000;
    SolverParams plain = exact;
    plain.active_set = false;
    plain.anderson = 0;
    const ContactSolution previous = BipotentialSolver(plain).solve(rp.pb, {}, {});
    REQUIRE(previous.converged);
    drift(rp.pb, 0.5, gen);  // the next stage's problem: the warm start is no longer its solution
    rp.pb.q0[c] = 0.07;
    const ContactSolution reference = BipotentialSolver(plain).solve(rp.pb, {}, {});
    REQUIRE(reference.converged);
    Eigen::VectorXd start = previous.Rbar;
    start[c] = 0.01;
    const ContactSolution s = BipotentialSolver(exact).solve(rp.pb, start, previous.u);
    INFO("trial " << trial << ": pair 2 " << int(s.status[2]) << ", Rbar " << s.Rbar.segment<2>(c).transpose());
    REQUIRE(s.converged);
    require_solution(rp.pb, s);
    CHECK(s.u[c] == 0.07);
    if (s.status[2] != Status::Stick) continue;
    ++stuck;
    CHECK(std::abs(s.Rbar[c]) <= 1e-12);
    Eigen::VectorXd d = s.Rbar - reference.Rbar;
    d[c] = 0.0;
    CHECK(d.norm() <= 1e-8 * (1 + reference.Rbar.norm()));
  }
  CHECK(stuck >= 3);
}
