// B1 and B2 from config/ (docs/BENCHMARKS.md): physics that must hold at every accepted step.
#include "helpers.hpp"
#include "rccm/base/config.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/app/simulation.hpp"

#include <catch2/catch.hpp>

using namespace rccm;

namespace {

using test::shipped;

/// Checks, at every accepted step: beta in [0, 1] and non-increasing at every node, and the
/// Signorini-Coulomb residuals of the committed contact state; records when each node first
/// falls below 1/2.
struct StepChecks {
  Eigen::VectorXd previous;
  std::vector<double> half_time;
  int steps = 0;
  double worst_residual = 0, worst_increase = 0, beta_min = 1, beta_max = 0;

  void operator()(const AcceptedStep& a) {
    const Eigen::VectorXd& beta = a.state.beta;
    if (previous.size() == 0) {
      previous = beta;
      half_time.assign(beta.size(), -1);
    }
    worst_increase = std::max(worst_increase, (beta - previous).maxCoeff());
    beta_min = std::min(beta_min, beta.minCoeff());
    beta_max = std::max(beta_max, beta.maxCoeff());
    worst_residual = std::max(worst_residual, a.residuals.max());
    for (Eigen::Index i = 0; i < beta.size(); ++i)
      if (half_time[i] < 0 && beta[i] < 0.5) half_time[i] = a.t;
    previous = beta;
    ++steps;
  }

  void require_invariants() const {
    CHECK(beta_min >= 0.0);
    CHECK(beta_max <= 1.0);
    CHECK(worst_increase <= 0.0);
    CHECK(worst_residual <= 1e-8);
  }
};

/// A peel from the left end: the first node to lose its adhesion is node 0, under the pulled
/// corner, and the debonded zone is a contiguous run from it that grows between the two
/// output times and has started, without reaching the far end, at the second.
void require_peeling_front(const StepChecks& checks, const RunResult& r) {
  REQUIRE(checks.half_time[0] >= 0);
  for (std::size_t i = 1; i < checks.half_time.size(); ++i)
    if (checks.half_time[i] >= 0) CHECK(checks.half_time[i] >= checks.half_time[i - 1]);
  REQUIRE(r.snapshots.size() >= 2);
  const Eigen::VectorXd& b_t1 = r.snapshots[0].beta;
  const Eigen::VectorXd& b_t2 = r.snapshots[1].beta;
  CHECK((b_t2.array() < 0.5).count() >= (b_t1.array() < 0.5).count());
  CHECK((b_t2.array() < 0.5).count() >= 1);
  CHECK((b_t2.array() < 0.5).count() < b_t2.size());  // the layer is not gone at t2
}

RunResult run(const std::string& file, const std::vector<std::string>& overrides, StepChecks& checks) {
  RunOptions options;
  options.observer = std::ref(checks);
  return Simulation(load_config(shipped(file), overrides), options).run();
}

}  // namespace

TEST_CASE("B1 peel: invariants at every step, debonding starts at the loaded end and advances", "[benchmark]") {
  for (const char* method : {"arkode", "euler", "rate-independent"}) {
    StepChecks checks;
    const RunResult r = run("b1.cfg", {std::string("integrator.method=") + method}, checks);
    INFO(method << ": " << checks.steps << " steps, worst residual " << checks.worst_residual);
    checks.require_invariants();
    require_peeling_front(checks, r);
    CHECK((r.snapshots[0].beta.array() < 0.5).count() >= 1);  // B1 has begun to peel at t1
  }
}

TEST_CASE("The README's first config (a coating peeled from its substrate) peels like B1", "[benchmark]") {
  StepChecks checks;
  const RunResult r = run("coating.cfg", {}, checks);
  checks.require_invariants();
  require_peeling_front(checks, r);
}

TEST_CASE("B2 shear: invariants at every step, pure Coulomb sliding once beta is gone", "[benchmark]") {
  StepChecks checks;
  const RunResult r = run("b2.cfg", {}, checks);
  checks.require_invariants();
  const Snapshot& end = r.snapshots.back();
  CHECK(end.beta.maxCoeff() < 1e-3);  // docs/BENCHMARKS.md: beta falls almost uniformly
  for (Eigen::Index i = 0; i < end.beta.size(); ++i) {
    const double Rt = end.Rbar[2 * i], Rn = end.Rbar[2 * i + 1];
    INFO("node " << i);
    CHECK(Rn > 0);                                                   // compressed
    CHECK(std::abs(Rt) == Approx(0.2 * (1 - end.beta[i]) * Rn).epsilon(1e-8));  // sliding at mubar Rn
    CHECK(Rt < 0);                                                   // opposing the +x shear
  }
}

TEST_CASE("B1: ARKODE results converge as the tolerance tightens", "[benchmark]") {
  // beta along the interface at t1 and t2, and at B at t1, against a run at rtol 1e-7: the
  // global error follows the tolerance (within 5 rtol) and shrinks with it.
  StepChecks ignore;
  const auto at = [&](const char* rtol) {
    return run("b1.cfg", {std::string("integrator.rtol=") + rtol, "integrator.atol=1e-14"}, ignore);
  };
  const RunResult ref = at("1e-7");
  std::vector<double> errors, errors_B;
  for (const char* rtol : {"1e-2", "1e-3", "1e-4", "1e-5"}) {
    const RunResult r = at(rtol);
    double e = 0;
    for (std::size_t k = 0; k < 2; ++k) e = std::max(e, (r.snapshots[k].beta - ref.snapshots[k].beta).cwiseAbs().maxCoeff());
    errors.push_back(e);
    errors_B.push_back(std::abs(r.snapshots[0].beta[0] - ref.snapshots[0].beta[0]) / ref.snapshots[0].beta[0]);
  }
  INFO("profile errors " << errors[0] << " " << errors[1] << " " << errors[2] << " " << errors[3]
                         << "; relative at B " << errors_B[0] << " " << errors_B[1] << " " << errors_B[2] << " "
                         << errors_B[3]);
  const double rtols[] = {1e-2, 1e-3, 1e-4, 1e-5};
  for (int k = 0; k < 4; ++k) CHECK(errors[k] < 5 * rtols[k]);
  for (int k = 0; k < 3; ++k) CHECK(errors[k + 1] < errors[k]);
  // beta at B is ~5e-10 (atol 1e-14): at rtol 1e-2 its relative error is noise (0.84 or 0.004
  // depending on the contact solver's round-off); from rtol 1e-3 on, tightening cuts it tenfold.
  CHECK(errors_B[2] < 0.1 * errors_B[1]);
  CHECK(errors_B[3] < 0.1 * errors_B[1]);
}

TEST_CASE("B1 stiff (alpha = 1e-3): the implicit integrator finishes in bounded steps, Euler-210 says it is unstable",
          "[benchmark]") {
  // Until t = 8 s (the same ramp, 0.24 mm at 8 s): past ~9 s the last nodes let go, the layer
  // is held by point A alone and whether ARKODE gets through that near-singular end depends
  // on round-off.
  StepChecks checks;
  const RunResult r = run("b1.cfg", {"interface.alpha=1e-3", "time.T=8", "loads.[0].value=0.24"}, checks);
  INFO(r.integrator.steps << " steps");
  CHECK(r.integrator.steps <= 10000);
  checks.require_invariants();
  StepChecks euler_checks;
  try {
    const RunResult e = run("b1.cfg", {"interface.alpha=1e-3", "time.T=8", "loads.[0].value=0.24", "integrator.method=euler"}, euler_checks);
    REQUIRE(!e.warnings.empty());
    CHECK_THAT(e.warnings[0], Catch::Contains("unstable"));
  } catch (const SolveError& e) {  // or it fails, and says why
    CHECK_THAT(e.what(), Catch::Contains("explicit Euler was unstable"));
  }
}
