// The integrators on the beta ODE of one node under a prescribed opening u_n = v t, posed
// directly as a BetaSystem: no mesh, no contact solve (docs/ARCHITECTURE.md: integrators see
// only the abstract system). Closed form in closed_form.hpp.
#include "closed_form.hpp"
#include "rccm/time/arkode_integrator.hpp"
#include "rccm/time/contact_only_integrator.hpp"
#include "rccm/time/euler_integrator.hpp"
#include "rccm/time/rate_independent_integrator.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rccm;

namespace {

/// alpha beta' = -(C v^2 t^2 beta - w)^+ for `n` identical nodes, committed by accept().
class ScalarOpening final : public BetaSystem {
 public:
  ScalarOpening(double C, double v, double w, double alpha, int n = 1)
      : C_(C), v_(v), w_(w), alpha_(alpha), beta_(Eigen::VectorXd::Ones(n)) {}
  int size() const override { return static_cast<int>(beta_.size()); }
  double committed_time() const override { return t_; }
  const Eigen::VectorXd& committed_beta() const override { return beta_; }
  int steps() const override { return steps_; }
  void rhs(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> f) override {
    ++evaluations;
    for (int i = 0; i < size(); ++i) f[i] = -std::max(0.0, energy(t) * beta[i] - w_) / alpha_;
  }
  void jacobian_diagonal(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> J) override {
    for (int i = 0; i < size(); ++i) J[i] = energy(t) * beta[i] > w_ ? -energy(t) / alpha_ : 0.0;
  }
  void rate_independent_beta(double t, const Eigen::VectorXd&, Eigen::Ref<Eigen::VectorXd> out) override {
    for (int i = 0; i < size(); ++i) out[i] = energy(t) > 0 ? std::min(beta_[i], w_ / energy(t)) : beta_[i];
  }
  void accept(double t, Eigen::Ref<Eigen::VectorXd> beta) override {
    beta = beta.cwiseMax(0.0).cwiseMin(beta_);
    t_ = t;
    beta_ = beta;
    ++steps_;
  }
  double exact(double t) const { return test::exact_beta(t, C_, v_, w_, alpha_, 1.0); }
  long evaluations = 0;

 private:
  double energy(double t) const { return C_ * v_ * v_ * t * t; }
  double C_, v_, w_, alpha_, t_ = 0;
  Eigen::VectorXd beta_;
  int steps_ = 0;
};

}  // namespace

TEST_CASE("ARKODE on the scalar system: the closed form to its tolerance, implicit and explicit", "[integrator]") {
  for (double alpha : {0.01, 1.0, 100.0}) {
    ScalarOpening ode(2e5, 0.03, 1e-6, alpha);  // the B1 interface, stiff for small alpha
    IntegratorParams p;
    p.rtol = 1e-8;
    p.atol = 1e-12;
    ArkodeIntegrator arkode(ode, p, 10.0);
    for (double t : {0.5, 2.0, 10.0}) {
      arkode.advance(t);
      INFO("alpha " << alpha << " t " << t);
      CHECK(ode.committed_time() == t);  // the output time exactly
      CHECK(ode.committed_beta()[0] == Approx(ode.exact(t)).margin(1e-6));
    }
    CHECK(arkode.stats().steps > 0);
  }
  ScalarOpening ode(2e5, 0.03, 1e-6, 100.0);
  IntegratorParams p;
  p.scheme = ArkodeScheme::Erk;
  p.rtol = 1e-8;
  p.atol = 1e-12;
  ArkodeIntegrator erk(ode, p, 10.0);
  erk.advance(10.0);
  CHECK(ode.committed_beta()[0] == Approx(ode.exact(10.0)).margin(1e-6));
}

TEST_CASE("explicit Euler on the scalar system: first order, and it says when it is unstable", "[integrator]") {
  const double T = 10.0;
  double previous = 0;
  for (int steps : {400, 800, 1600}) {
    ScalarOpening ode(1e3, 0.01, 1e-3, 1.0);
    EulerIntegrator euler(ode, time_grid(T, steps, {}));
    euler.advance(T);
    const double e = std::abs(ode.committed_beta()[0] - ode.exact(T));
    if (previous > 0) CHECK(std::log2(previous / e) == Approx(1.0).margin(0.1));
    previous = e;
    CHECK(euler.warnings().empty());
    CHECK(euler.stats().steps == steps);
    CHECK(ode.evaluations == steps);  // one f per step
  }
  ScalarOpening stiff(2e5, 0.03, 1e-6, 1.0);  // dt C u^2 / alpha ~ 860 at 210 steps
  EulerIntegrator euler(stiff, time_grid(T, 210, {}));
  euler.advance(T);
  REQUIRE(euler.warnings().size() == 1);
  // The first step past dt C u^2 / alpha = 1 overshoots beta = 0 (ratio 1.24): clamped, and
  // beta stays 0 (no rate left: the ratio does not grow further). Said as an overshoot, not as
  // an instability whose ratio (1.24) contradicts "stable below 2".
  CHECK_THAT(euler.warnings()[0], Catch::Contains("explicit Euler overshot beta = 0") && Catch::Contains("clamped") &&
                                      !Catch::Contains("unstable"));
  CHECK(stiff.committed_beta()[0] >= 0.0);  // clamped, never negative
  // dt C v^2 t^2 / alpha would reach 0.1 x 0.15 x 100 = 1.5 at T; with w = 0 the first step
  // past 1 passes beta = 0.
  ScalarOpening overshoot(0.15, 1.0, 0.0, 1.0);
  EulerIntegrator coarse(overshoot, time_grid(T, 100, {}));
  coarse.advance(T);
  REQUIRE(coarse.warnings().size() == 1);
  CHECK_THAT(coarse.warnings()[0], Catch::Contains("explicit Euler overshot beta = 0: dt (Cn u_n^2 + Ct u_t^2) / alpha reached 1.") &&
                                       Catch::Contains("clamped") && !Catch::Contains("unstable") && !Catch::Contains("more than"));
}

TEST_CASE("the rate-independent integrator is exact on the scalar system: contact-only keeps beta", "[integrator]") {
  ScalarOpening ode(2e5, 0.03, 1e-6, 1.0, 3);
  IntegratorParams p;
  RateIndependentIntegrator ri(ode, time_grid(10.0, 50, {3.571}), p, 0.0);  // an exact "contact solve"
  for (double t : {3.571, 10.0}) {
    ri.advance(t);
    CHECK(ode.committed_beta()[1] == Approx(test::rate_independent_beta(t, 2e5, 0.03, 1e-6, 1.0)).epsilon(1e-14));
  }
  ScalarOpening held(2e5, 0.03, 1e-6, 1.0, 2);
  ContactOnlyIntegrator contact_only(held, time_grid(10.0, 7, {}));
  contact_only.advance(10.0);
  CHECK(held.committed_beta() == Eigen::VectorXd::Ones(2));
  CHECK(held.steps() == 7);
}

TEST_CASE("the time grids: equal steps with the output times added, stops at the output times and T",
          "[integrator]") {
  const std::vector<double> grid = time_grid(10.0, 4, {3.0, 5.0, 0.0});
  CHECK(grid == std::vector<double>{2.5, 3.0, 5.0, 7.5, 10.0});
  CHECK(stop_times(10.0, {3.0, 10.0, 0.0}) == std::vector<double>{0.0, 3.0, 10.0});
  CHECK(stop_times(10.0, {3.0}) == std::vector<double>{3.0, 10.0});
  // An output time at T to round-off (1e-12 T) is T: the run still ends at T, not short of it.
  CHECK(stop_times(1.0, {0.5, 0.999999999999}) == std::vector<double>{0.5, 1.0});
  CHECK(time_grid(1.0, 4, {0.999999999999}) == std::vector<double>{0.25, 0.5, 0.75, 1.0});
}
