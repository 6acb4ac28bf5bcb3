#include "rccm/time/integrator.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/time/arkode_integrator.hpp"
#include "rccm/time/contact_only_integrator.hpp"
#include "rccm/time/euler_integrator.hpp"
#include "rccm/time/rate_independent_integrator.hpp"

#include <algorithm>
#include <cmath>

namespace rccm {

IntegratorStats operator+(const IntegratorStats& a, const IntegratorStats& b) {
  return {a.steps + b.steps, a.rejected + b.rejected, a.rhs_evaluations + b.rhs_evaluations,
          a.newton_iterations + b.newton_iterations, b.slices};
}

void FixedStepIntegrator::advance(double t_out) {
  const double eps = 1e-12 * std::max(1.0, std::abs(t_out));
  for (double t : grid_) {
    if (t <= ode_.committed_time() + eps) continue;
    if (t > t_out + eps) break;
    last_step_ = t - ode_.committed_time();
    step(t);
    ++stats_.steps;
  }
  RCCM_VERIFY(std::abs(ode_.committed_time() - t_out) <= eps, "fixed-step grid misses an output time");
}

namespace {

std::vector<double> merge_times(std::vector<double> t, double T) {
  std::sort(t.begin(), t.end());
  const double eps = 1e-12 * T;
  t.erase(std::unique(t.begin(), t.end(), [eps](double a, double b) { return std::abs(a - b) <= eps; }), t.end());
  t.erase(std::remove_if(t.begin(), t.end(), [eps](double x) { return x <= eps; }), t.end());
  if (!t.empty() && T - t.back() <= eps) t.back() = T;  // a time at T to round-off is T: the run ends there
  return t;
}

}  // namespace

std::vector<double> time_grid(double T, int steps, const std::vector<double>& output_times) {
  std::vector<double> t = output_times;
  for (int n = 1; n <= steps; ++n) t.push_back(T * n / steps);
  return merge_times(t, T);
}

std::vector<double> stop_times(double T, const std::vector<double>& output_times) {
  std::vector<double> t = output_times;
  t.push_back(T);
  std::vector<double> stops = merge_times(t, T);
  // An output time of 0 is the initial state: a stop that needs no step.
  if (!output_times.empty() && *std::min_element(output_times.begin(), output_times.end()) <= 1e-12 * T)
    stops.insert(stops.begin(), 0.0);
  return stops;
}

std::unique_ptr<BetaIntegrator> make_integrator(BetaSystem& ode, const Config& cfg, double initial_step) {
  IntegratorParams p = cfg.integrator;
  if (initial_step > 0 && p.initial_step == 0) p.initial_step = initial_step;
  const std::vector<double> grid = time_grid(cfg.time.T, cfg.time.steps, cfg.output.times);
  switch (p.method) {
    case Method::Arkode: return std::make_unique<ArkodeIntegrator>(ode, p, cfg.time.T);
    case Method::Euler: return std::make_unique<EulerIntegrator>(ode, grid);
    case Method::RateIndependent: return std::make_unique<RateIndependentIntegrator>(ode, grid, p, cfg.solver.tolerance);
    case Method::ContactOnly: return std::make_unique<ContactOnlyIntegrator>(ode, grid);
  }
  throw InternalError("unknown integrator method");
}

}  // namespace rccm
