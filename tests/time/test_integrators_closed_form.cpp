// The beta integrators against the single-node closed form (docs/MODEL.md s3, s6) through the
// whole pipeline (config, model, contact solve, integrator): every contact node's displacement
// is prescribed, u_n = v t exactly, so each node follows the single-node ODE.
#include "closed_form.hpp"
#include "helpers.hpp"
#include "rccm/app/simulation.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

using namespace rccm;

namespace {

struct Opening {
  double C, v, w, alpha, T = 10.0;
};

std::string opening_config(const Opening& o) {
  return R"(
mesh = { size = [4.0, 1.0]; nx = 2; ny = 1; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = )" + std::to_string(o.C) + "; Ct = " + std::to_string(o.C) +
         "; w = " + std::to_string(o.w) + "; alpha = " + std::to_string(o.alpha) + R"(; mu = 0.2; };
loads = (
  { node_set = "bottom"; type = "displacement"; component = "x"; value = 0.0; },
  { node_set = "bottom"; type = "displacement"; component = "y"; value = )" +
         std::to_string(o.v * o.T) + R"(; }
);
time = { T = )" + std::to_string(o.T) + R"(; steps = 200; };
output = { times = [0.5, 1.0, 2.0, 5.0]; };
)";
}

/// Largest error of beta (every node, every output time) against `exact`.
template <class Exact>
double max_error(const RunResult& r, Exact exact, bool relative = false) {
  double e = 0;
  for (const Snapshot& s : r.snapshots)
    for (Eigen::Index i = 0; i < s.beta.size(); ++i) {
      const double ref = exact(s.t);
      e = std::max(e, std::abs(s.beta[i] - ref) / (relative ? ref : 1.0));
    }
  return e;
}

RunResult run(const Opening& o, const std::vector<std::string>& overrides) {
  return Simulation(test::config_from_text(opening_config(o), overrides)).run();
}

}  // namespace

TEST_CASE("closed form: the integrating-factor solution satisfies the ODE", "[integrator]") {
  // An independent check of the reference itself: finite-difference residual of the ODE.
  const double C = 2e5, v = 0.03, w = 1e-6;
  for (double alpha : {0.01, 1.0, 100.0})
    for (double t : {0.5, 2.0, 7.0}) {
      const double h = 1e-5 * t;
      const double b = test::exact_beta(t, C, v, w, alpha, 1.0);
      const double db = (test::exact_beta(t + h, C, v, w, alpha, 1.0) - test::exact_beta(t - h, C, v, w, alpha, 1.0)) / (2 * h);
      const double rhs = -std::max(0.0, C * v * v * t * t * b - w) / alpha;
      INFO("alpha " << alpha << " t " << t);
      CHECK(db == Approx(rhs).epsilon(1e-5).margin(1e-14));
    }
}

TEST_CASE("ARKODE at rtol 1e-8 follows the closed form within 1e-6, alpha 0.01 to 100", "[integrator]") {
  for (double alpha : {0.01, 0.1, 1.0, 10.0, 100.0}) {
    const Opening o{2e5, 0.03, 1e-6, alpha};  // the B1 interface
    const RunResult r = run(o, {"integrator.rtol=1e-8", "integrator.atol=1e-12"});
    const double e = max_error(r, [&](double t) { return test::exact_beta(t, o.C, o.v, o.w, o.alpha, 1.0); });
    INFO("alpha " << alpha << ": max error " << e << " in " << r.integrator.steps << " steps");
    CHECK(e <= 1e-6);
  }
  // The explicit table too, where the ODE is not stiff.
  for (double alpha : {10.0, 100.0}) {
    const Opening o{2e5, 0.03, 1e-6, alpha};
    const RunResult r = run(o, {"integrator.scheme=erk", "integrator.rtol=1e-8", "integrator.atol=1e-12"});
    const double e = max_error(r, [&](double t) { return test::exact_beta(t, o.C, o.v, o.w, o.alpha, 1.0); });
    INFO("erk alpha " << alpha << ": max error " << e);
    CHECK(e <= 1e-6);
  }
}

TEST_CASE("rate-independent integrator is exact on a prescribed opening", "[integrator]") {
  const Opening o{2e5, 0.03, 1e-6, 0.0};
  const RunResult r = run(o, {"integrator.method=rate-independent"});
  CHECK(max_error(r, [&](double t) { return test::rate_independent_beta(t, o.C, o.v, o.w, 1.0); }, true) <= 1e-12);
}

TEST_CASE("as alpha -> 0 the viscous solution approaches the rate-independent one", "[integrator]") {
  std::vector<double> errors;
  for (double alpha : {1.0, 0.1, 0.01, 0.001}) {
    const Opening o{1e3, 0.01, 1e-3, alpha};
    const RunResult r = run(o, {"integrator.rtol=1e-8", "integrator.atol=1e-12"});
    errors.push_back(max_error(r, [&](double t) { return test::rate_independent_beta(t, o.C, o.v, o.w, 1.0); }, true));
  }
  INFO("relative distance to the rate-independent limit: " << errors[0] << " " << errors[1] << " " << errors[2]
                                                           << " " << errors[3]);
  for (std::size_t k = 1; k < errors.size(); ++k) CHECK(errors[k] < 0.5 * errors[k - 1]);
}

TEST_CASE("explicit Euler past beta = 0 says so", "[integrator]") {
  // B1's interface: C u^2 / alpha would reach ~860 / dt at 210 steps, but the first step past
  // dt C u^2 / alpha = 1 (1.24) takes beta below 0, where it is clamped and stays.
  const Opening o{2e5, 0.03, 1e-6, 1.0};
  const RunResult r = run(o, {"integrator.method=euler", "time.steps=210"});
  REQUIRE(r.warnings.size() == 1);
  CHECK_THAT(r.warnings[0], Catch::Contains("overshot beta = 0") && Catch::Contains("clamped"));
}

TEST_CASE("time convergence orders on the closed form: Euler 1, ARKODE's DIRK and ERK tables their order",
          "[integrator][order]") {
  // The kink of the RHS at t0 = 0.1 s lies on every grid, so each scheme shows its full order.
  const Opening o{1e3, 0.01, 1e-3, 1.0};
  const auto exact = [&](double t) { return test::exact_beta(t, o.C, o.v, o.w, o.alpha, 1.0); };
  struct Study {
    const char* name;
    std::vector<std::string> settings;
    double order;  // expected
  };
  const std::vector<Study> studies = {
      {"euler", {"integrator.method=euler"}, 1.0},
      {"arkode dirk", {"integrator.scheme=dirk", "integrator.rtol=1e-12", "integrator.atol=1e-14"}, 4.0},
      {"arkode erk", {"integrator.scheme=erk"}, 4.0},
  };
  std::cout << "scheme  dt [s]  max error  observed order\n";
  for (const Study& s : studies) {
    double previous = 0;
    for (double dt : {0.1, 0.05, 0.025, 0.0125}) {
      std::vector<std::string> set = s.settings;
      set.push_back("time.steps=" + std::to_string(static_cast<int>(std::lround(o.T / dt))));
      if (std::string(s.name) != "euler") set.push_back("integrator.fixed_step=" + std::to_string(dt));  // ARKODE's
      const RunResult r = run(o, set);
      CHECK(r.warnings.empty());  // Euler stays below its stability limit on these grids
      const double e = max_error(r, exact);
      const double order = previous > 0 ? std::log2(previous / e) : 0.0;
      std::cout << s.name << "  " << dt << "  " << e << "  " << order << "\n";
      INFO(s.name << " dt " << dt << ": error " << e << ", observed order " << order);
      if (dt < 0.05) CHECK(order == Approx(s.order).margin(0.15));
      previous = e;
    }
  }
}

TEST_CASE("ARKODE at a fixed step rejects no step: stage solves retried with a fresh Jacobian are not rejections",
          "[integrator]") {
  // B1 at integrator.fixed_step = 0.01 s: 1000 steps and the two output times' short ones. Its
  // stages' Newton iterations fail 14 times with an out-of-date Jacobian and converge with a
  // fresh one at the same step (a fixed step is never cut: a stage that still fails stops the
  // run); those were once counted as rejected steps.
  const RunResult r =
      Simulation(load_config(test::shipped("b1.cfg"), {"integrator.fixed_step=0.01"}), RunOptions{}).run();
  REQUIRE(r.stopped.empty());
  CHECK(r.integrator.rejected == 0);
  CHECK(r.integrator.steps == 1002);
  CHECK(r.steps.size() == 1003);  // each step tried once: every accepted step recorded once, with t = 0
}
