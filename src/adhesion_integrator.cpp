#include "rccm/adhesion_integrator.hpp"

#include "rccm/arkode_integrator.hpp"
#include "rccm/errors.hpp"
#include "rccm/euler_integrator.hpp"
#include "rccm/rate_independent_integrator.hpp"
#include "rccm/simulation.hpp"

namespace rccm {

IntegratorStats operator+(const IntegratorStats& a, const IntegratorStats& b) {
  return {a.steps + b.steps, a.rejected + b.rejected, a.rhs_evaluations + b.rhs_evaluations,
          a.newton_iterations + b.newton_iterations};
}

FixedStepIntegrator::FixedStepIntegrator(BetaOde& ode, const Config& cfg) : ode_(ode), grid_(time_grid(cfg)) {}

void FixedStepIntegrator::advance(double t_out) {
  const double eps = 1e-12 * std::max(1.0, std::abs(t_out));
  for (double t : grid_) {
    if (t <= ode_.committed().t + eps) continue;
    if (t > t_out + eps) break;
    last_step_ = t - ode_.committed().t;
    step(t);
    ++stats_.steps;
  }
  RCCM_VERIFY(std::abs(ode_.committed().t - t_out) <= eps, "fixed-step grid misses an output time");
}

namespace {

/// beta held at its committed value: contact steps only (pure Signorini-Coulomb with beta0 = 0).
class FixedBetaIntegrator final : public FixedStepIntegrator {
 public:
  using FixedStepIntegrator::FixedStepIntegrator;

 private:
  void step(double t_new) override {
    Eigen::VectorXd beta = ode_.committed().beta;
    ode_.accept(t_new, beta);
  }
};

}  // namespace

std::unique_ptr<AdhesionIntegrator> make_integrator(BetaOde& ode, const Config& cfg) {
  switch (cfg.integrator.method) {
    case Method::Arkode: return std::make_unique<ArkodeIntegrator>(ode, cfg);
    case Method::Euler: return std::make_unique<EulerIntegrator>(ode, cfg);
    case Method::RateIndependent: return std::make_unique<RateIndependentIntegrator>(ode, cfg);
    default: return std::make_unique<FixedBetaIntegrator>(ode, cfg);
  }
}

}  // namespace rccm
