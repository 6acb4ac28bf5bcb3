#include "rccm/simulation.hpp"

#include "rccm/beta_ode.hpp"
#include "rccm/body_state.hpp"
#include "rccm/errors.hpp"
#include "rccm/model.hpp"
#include "rccm/output_directory.hpp"
#include "rccm/result_writer.hpp"
#include "rccm/run_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>

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

void progress_line(const AcceptedStep& a, double T) {
  std::fprintf(stderr, "\r  t = %9.5f s (%5.1f %%)  dt = %8.2e  min beta = %10.4e  sweeps/solve = %4.1f   ", a.t,
               100 * a.t / T, a.dt, a.state.beta.minCoeff(),
               double(a.counts.sweeps) / std::max(1L, a.counts.contact_solves));
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

  // 1. Set up: mesh, body (K0 factorized once), interface, condensation; the output
  //    directory is checked first, so that a long setup is not wasted.
  if (options_.write_files) check_output_directory(cfg_, options_.force);
  const Model model(cfg_);
  result.setup_seconds = seconds_since(start);
  result.watched = model.watched();
  result.nodes = static_cast<int>(model.mesh().nodes.size());
  result.cells = static_cast<int>(model.mesh().cells.size());
  result.dofs = 2 * result.nodes;
  result.contact_nodes = model.contact_nodes();
  if (options_.step_log)
    *options_.step_log << "# " << cfg_.file << ": " << result.nodes << " nodes, " << result.cells << " cells, "
                       << result.contact_nodes << " contact nodes; integrator " << method_name(cfg_.integrator.method)
                       << "\n#  step      t [s]    dt [s] solves sweeps(mean max)  residual    min beta stick slide   sep\n";

  // 2. Result files, only now that the input is known to be good.
  std::unique_ptr<OutputDirectory> directory;
  std::unique_ptr<ResultWriter> writer;
  if (options_.write_files) {
    directory = std::make_unique<OutputDirectory>(cfg_);
    writer = std::make_unique<ResultWriter>(model, directory->path());
  }

  // 3. The beta ODE; each accepted step updates the energy balance, the files and the logs.
  std::unique_ptr<EnergyBalance> energy;
  BodyState body;  // of the last accepted step
  BetaOde ode(model, cfg_.solver, [&](const AcceptedStep& a) {
    body = body_state(model, a.state);
    if (!energy) energy = std::make_unique<EnergyBalance>(model, a.state, body);
    else energy->add(a.state, body);
    result.peak_force.resize(body.force.size(), 0.0);
    result.peak_time.resize(body.force.size(), 0.0);
    for (std::size_t k = 0; k < body.force.size(); ++k)
      if (std::abs(body.force[k]) > std::abs(result.peak_force[k]))
        result.peak_force[k] = body.force[k], result.peak_time[k] = a.t;
    result.steps.push_back({a.step, a.t, a.dt, a.counts.contact_solves,
                            double(a.counts.sweeps) / std::max(1L, a.counts.contact_solves), a.counts.max_sweeps,
                            a.cpu_seconds});
    if (writer) writer->step(a, body, energy->terms());
    if (options_.step_log) log_step(*options_.step_log, a);
    if (options_.progress) progress_line(a, cfg_.time.T);
    if (options_.observer) options_.observer(a);
  });
  Eigen::VectorXd beta0 = model.initial_beta();
  ode.accept(0.0, beta0);
  const std::unique_ptr<AdhesionIntegrator> integrator = make_integrator(ode, cfg_);

  // 4. Integrate to each output time exactly; write the interface and the mesh there.
  const auto snapshot = [&]() {
    const InterfaceState& s = ode.committed();
    const double debonded = (s.beta.array() < 0.5).select(model.interface().a.array(), 0.0).sum();
    result.snapshots.push_back({s.t, s.beta, s.Rbar, s.u, debonded});
    if (writer) writer->output(s, body);  // the last accepted step is the one at s.t
  };
  // 5. Report (also of a run that stops early, with its last accepted state).
  const auto report = [&]() {
    if (options_.progress) std::fputs("\n", stderr);
    result.integrator = integrator->stats();
    result.solves = ode.totals();
    result.energy = energy->terms();
    result.warnings = integrator->warnings();
    result.wall_seconds = seconds_since(start);
    if (writer) write_reports(writer->directory(), cfg_, result);
  };
  std::exception_ptr stop;
  try {
    for (double t_out : stop_times(cfg_)) {
      integrator->advance(t_out);
      snapshot();
    }
  } catch (const SolveError& e) {
    result.stopped = std::string("failed: ") + e.what();
    stop = std::current_exception();
  } catch (const Interrupted& e) {
    result.stopped = e.what();
    stop = std::current_exception();
  }
  if (stop && (result.snapshots.empty() || result.snapshots.back().t < ode.committed().t)) snapshot();
  report();
  if (stop) std::rethrow_exception(stop);
  return result;
}

}  // namespace rccm
