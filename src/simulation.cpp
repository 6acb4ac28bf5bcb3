#include "rccm/simulation.hpp"

#include "rccm/beta_ode.hpp"
#include "rccm/body_state.hpp"
#include "rccm/checkpoint.hpp"
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
  //    directory (or the checkpoint to restart from) is checked first, so that a long setup
  //    is not wasted.
  std::unique_ptr<Checkpoint> resume;
  if (options_.restart) resume = std::make_unique<Checkpoint>(read_checkpoint(cfg_.output.directory, cfg_));
  else if (options_.write_files) check_output_directory(cfg_, options_.force);
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

  // 2. Result files, only now that the input is known to be good; a restart takes up the
  //    files of the run it continues at the checkpoint.
  std::unique_ptr<OutputDirectory> directory;
  std::unique_ptr<ResultWriter> writer;
  if (options_.write_files) {
    directory = std::make_unique<OutputDirectory>(cfg_);
    ResumePoint point;
    if (resume) {
      point.t = resume->state.t;
      for (const Snapshot& s : resume->progress.snapshots) point.output_times.push_back(s.t);
    }
    writer = std::make_unique<ResultWriter>(model, directory->path(), resume ? &point : nullptr);
  }

  // 3. The beta ODE; each accepted step updates the energy balance, the files and the logs,
  //    and every output.checkpoint_steps steps a checkpoint.
  std::unique_ptr<EnergyBalance> energy;
  BodyState body;  // of the last accepted step
  std::unique_ptr<AdhesionIntegrator> integrator;
  IntegratorStats earlier;                // counts of the run a restart continues
  const auto save_checkpoint = [&](const BetaOde& ode) {
    Checkpoint c{cfg_.settings,          ode.steps(),     integrator->last_step(), ode.committed(),
                 energy->terms(),        integrator->diagnostics(), ode.excursion(), {}};
    c.progress.snapshots = result.snapshots;
    c.progress.steps = result.steps;
    c.progress.peak_force = result.peak_force;
    c.progress.peak_time = result.peak_time;
    c.progress.solves = ode.totals();
    c.progress.integrator = earlier + integrator->stats();
    c.progress.integrator.steps = ode.steps();  // also inside a step, before the scheme counts it
    write_checkpoint(writer->directory(), c);
  };
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
    if (writer && integrator && cfg_.output.checkpoint_steps > 0 && a.step % cfg_.output.checkpoint_steps == 0)
      save_checkpoint(ode);
    if (options_.observer) options_.observer(a);
  });
  Config integrator_config = cfg_;
  if (resume) {
    const InterfaceState initial = InterfaceState::initial(model);
    energy = std::make_unique<EnergyBalance>(model, initial, body_state(model, initial));
    ode.resume(resume->state, resume->step, resume->progress.solves);
    body = body_state(model, resume->state);
    energy->resume(resume->state, body, resume->energy);
    result.snapshots = resume->progress.snapshots;
    result.steps = resume->progress.steps;
    result.peak_force = resume->progress.peak_force;
    result.peak_time = resume->progress.peak_time;
    earlier = resume->progress.integrator;
    // ARKODE begins again where it was: with the last accepted step size, not an estimate.
    double& h0 = integrator_config.integrator.initial_step;
    if (h0 == 0) h0 = resume->last_step;
  } else {
    Eigen::VectorXd beta0 = model.initial_beta();
    ode.accept(0.0, beta0);
  }
  integrator = make_integrator(ode, integrator_config);
  if (resume) {
    integrator->restore(resume->diagnostics);
    ode.restore(resume->excursion);
  }

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
    result.integrator = earlier + integrator->stats();
    result.solves = ode.totals();
    result.energy = energy->terms();
    result.warnings = integrator->warnings();
    for (const std::string& w : ode.warnings()) result.warnings.push_back(w);
    result.wall_seconds = seconds_since(start);
    if (writer) write_reports(writer->directory(), cfg_, result);
  };
  std::exception_ptr stop;
  try {
    for (double t_out : stop_times(cfg_)) {
      const double eps = 1e-12 * cfg_.time.T;
      const bool reached = t_out <= ode.committed().t + eps;  // before a restart's checkpoint
      if (reached && !result.snapshots.empty() && result.snapshots.back().t >= t_out - eps) continue;
      if (!reached) integrator->advance(t_out);
      snapshot();
    }
  } catch (const SolveError& e) {
    result.stopped = std::string("failed: ") + e.what();
    stop = std::current_exception();
  } catch (const Interrupted& e) {
    result.stopped = e.what();
    stop = std::current_exception();
  }
  // The restart point: the last accepted state, before a stopped run's extra snapshot of it.
  if (writer) save_checkpoint(ode);
  if (stop && (result.snapshots.empty() || result.snapshots.back().t < ode.committed().t)) snapshot();
  report();
  if (stop) std::rethrow_exception(stop);
  return result;
}

}  // namespace rccm
