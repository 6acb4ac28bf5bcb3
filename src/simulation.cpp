#include "rccm/simulation.hpp"

#include "rccm/beta_ode.hpp"
#include "rccm/model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace rccm {

namespace {

std::vector<double> merge_times(std::vector<double> t, double T) {
  std::sort(t.begin(), t.end());
  const double eps = 1e-12 * T;
  t.erase(std::unique(t.begin(), t.end(), [eps](double a, double b) { return std::abs(a - b) <= eps; }), t.end());
  t.erase(std::remove_if(t.begin(), t.end(), [eps](double x) { return x <= eps; }), t.end());
  return t;
}

void log_step(std::ostream& out, const AcceptedStep& a) {
  int count[3] = {0, 0, 0};
  for (Status x : a.state.status) ++count[static_cast<int>(x)];
  char line[200];
  std::snprintf(line, sizeof line, "%6d %10.5f %9.2e %5ld %5.1f %4d %9.2e %11.4e %5d %5d %5d\n", a.step, a.t, a.dt,
                a.counts.contact_solves, double(a.counts.sweeps) / std::max(1L, a.counts.contact_solves),
                a.counts.max_sweeps, a.solution.residual, a.state.beta.minCoeff(), count[1], count[2], count[0]);
  out << line;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<double> time_grid(const Config& cfg) {
  std::vector<double> t = cfg.output.times;
  for (int n = 1; n <= cfg.time.steps; ++n) t.push_back(cfg.time.T * n / cfg.time.steps);
  return merge_times(t, cfg.time.T);
}

std::vector<double> stop_times(const Config& cfg) {
  std::vector<double> t = cfg.output.times;
  t.push_back(cfg.time.T);
  return merge_times(t, cfg.time.T);
}

RunResult Simulation::run() {
  const auto start = std::chrono::steady_clock::now();
  RunResult result;

  // 1. Set up: mesh, body (K0 factorized once), interface, condensation.
  const Model model(cfg_);
  result.setup_seconds = seconds_since(start);
  result.watched = model.watched();
  if (log_)
    *log_ << "# " << cfg_.file << ": " << model.mesh().nodes.size() << " nodes, " << model.mesh().cells.size()
          << " cells, " << model.contact_nodes() << " contact nodes; integrator " << method_name(cfg_.integrator.method)
          << "\n#  step      t [s]    dt [s] solves sweeps(mean max)  residual    min beta stick slide   sep\n";

  // 2. The beta ODE, its initial state committed at t = 0, and the integrator.
  BetaOde ode(model, cfg_.solver, [this](const AcceptedStep& a) {
    if (log_) log_step(*log_, a);
    if (observer_) observer_(a);
  });
  Eigen::VectorXd beta0 = model.initial_beta();
  ode.accept(0.0, beta0);
  const std::unique_ptr<AdhesionIntegrator> integrator = make_integrator(ode, cfg_);

  // 3. Integrate to each output time exactly.
  for (double t_out : stop_times(cfg_)) {
    integrator->advance(t_out);
    const InterfaceState& s = ode.committed();
    result.snapshots.push_back({s.t, s.beta, s.Rbar, s.u});
  }

  // 4. Report.
  result.integrator = integrator->stats();
  result.solves = ode.totals();
  result.warnings = integrator->warnings();
  result.wall_seconds = seconds_since(start);
  return result;
}

}  // namespace rccm
