#include "rccm/io/recorder.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/io/checkpoint.hpp"
#include "rccm/io/csv.hpp"
#include "rccm/io/output_directory.hpp"
#include "rccm/io/run_report.hpp"
#include "rccm/la/parallel.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>

namespace rccm {

namespace {

/// A run notes (note_deformation) when the displacement gradient |grad u|_2 exceeds this
/// over more than this fraction of a body's volume. 0.15: a rigid rotation by 0.15 rad alone
/// strains a linear model by 1 - cos 0.15 = 0.011, beyond the elastic range of a metal. The
/// shipped examples stay below the rule (coating-curved's pulled end reaches 0.141 in one cell
/// of 240, coating3d 0.102).
constexpr double small_strain_limit = 0.15;
constexpr double small_strain_fraction = 0.01;
/// Checks of the small strains over a run, evenly spaced in time: each is a solve of the whole
/// body (config/b1-million.cfg: at 200 checks 16 % of its run, at 50 about 7 %; 10^6 unknowns
/// out of core: minutes each, hence RunOptions::strain_check_share).
constexpr double deformation_checks = 50;

void log_step(std::ostream& out, const AcceptedStep& a) {
  int count[3] = {0, 0, 0};
  for (Status x : a.state.status) ++count[static_cast<int>(x)];
  char line[200];
  std::snprintf(line, sizeof line, "%6d %10.5f %9.2e %5ld %5.1f %4d %9.2e %11.4e %5d %5d %5d\n", a.step, a.t, a.dt,
                a.counts.contact_solves, a.counts.sweeps_per_solve(), a.counts.max_sweeps, a.solution.residual,
                a.state.beta.minCoeff(), count[1], count[2], count[0]);
  out << line;
}

void progress_line(const AcceptedStep& a, double T) {
  std::fprintf(stderr, "\r  t = %9.5f s (%5.1f %%)  dt = %8.2e  min beta = %10.4e  sweeps/solve = %4.1f   ", a.t,
               100 * a.t / T, a.dt, a.state.beta.minCoeff(), a.counts.sweeps_per_solve());
}

}  // namespace

Recorder::Recorder(const Config& cfg, RunOptions options)
    : cfg_(cfg),
      options_(std::move(options)),
      stops_(stop_times(cfg.time.T, cfg.output.times)),
      start_(std::chrono::steady_clock::now()) {
  if (!options_.restart) {
    if (options_.write_files) check_output_directory(cfg, options_.force);
    return;
  }
  resume_ = std::make_unique<Checkpoint>(read_checkpoint(cfg.output.directory, cfg));
  check_result_names(cfg);
  if (resume_->state.t >= cfg.time.T && holds_complete_run(cfg.output.directory))  // not a run cut off writing its end
    throw InputError(checkpoint_path(cfg.output.directory) + ": the run reached time.T = " + csv_number(cfg.time.T) +
                     " s: there is nothing to go on with, its results stand (to run it again: --force)");
}

double Recorder::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Recorder::open(const Model& model) {
  model_ = &model;
  small_strains_ = std::make_unique<SmallStrainCheck>(model.mesh());
  result_.setup_seconds = seconds();
  result_.watched = model.watched();
  result_.nodes = model.mesh().num_nodes();
  result_.cells = static_cast<int>(model.mesh().cells.size());
  result_.dofs = model.mesh().num_dofs();
  result_.contact_nodes = model.contact_nodes();
  result_.linear_solver = model.linear_solver();
  result_.flexibility = model.condensation().W0().storage();
  result_.bodies = model.mesh().body_names;
  result_.pairs_per_interface.assign(cfg_.interfaces.size(), 0);
  for (const ContactPair& c : model.interface().pairs) ++result_.pairs_per_interface[c.law];
  // Doubtful geometry said before the first step: a user can stop a long run at once, and a
  // run that fails has said it (the report's warnings repeat it at the end). Then the settings
  // this run's methods do not read: said, but no warning of the results (a sweep or a
  // comparison runs other methods on purpose).
  if (options_.write_files) {
    for (const std::string& note : model.notes()) say_note(note);
    for (const std::string& note : unused_settings(cfg_)) say_note(note);
  }
  if (options_.step_log)
    *options_.step_log << "# " << cfg_.file << ": " << result_.nodes << " nodes, " << result_.cells << " cells, "
                       << result_.contact_nodes << " contact nodes; integrator " << method_name(cfg_.integrator.method)
                       << "\n#  step      t [s]    dt [s] solves sweeps(mean max)  residual    min beta stick slide   sep\n";
  if (resume_ && (model.contact_nodes() != resume_->state.beta.size() ||
                  model.interface().layout.offset(model.contact_nodes()) != resume_->state.u.size()))
    throw InputError(checkpoint_path(cfg_.output.directory) + ": written for a model of " +
                     std::to_string(resume_->state.beta.size()) + " contact nodes, this one has " +
                     std::to_string(model.contact_nodes()) + "; start the run afresh with --force");
  if (resume_)
    for (int i = 0; i < model.contact_nodes(); ++i)
      if (model.interface().pairs[i].node != resume_->contact_nodes[i])
        throw InputError(checkpoint_path(cfg_.output.directory) + ": its contact node " + std::to_string(i) + " is mesh node " +
                         std::to_string(resume_->contact_nodes[i]) + ", this model's is " +
                         std::to_string(model.interface().pairs[i].node) +
                         " (written by another version of rccm?); start the run afresh with --force");
  if (!options_.write_files) return;
  directory_ = std::make_unique<OutputDirectory>(cfg_, options_.force);
  ResumePoint point;
  if (resume_) {
    point.t = resume_->state.t;
    for (const Snapshot& s : resume_->progress.snapshots) point.output_times.push_back(s.t);
    const int step = resume_->step, every = cfg_.output.every;
    point.frame_at_t = step == 0 || (every > 0 && step % every == 0) ||
                       (!point.output_times.empty() && point.output_times.back() == point.t);
  }
  writer_ = std::make_unique<ResultWriter>(model, cfg_, directory_->path(), resume_ ? &point : nullptr);
}

void Recorder::start(BetaOde& ode) {
  ode_ = &ode;
  if (!resume_) {
    Eigen::VectorXd beta0 = model_->initial_beta();
    ode.accept(0.0, beta0);  // step 0: recorded by step()
    return;
  }
  const InterfaceState initial = InterfaceState::initial(*model_);
  energy_ = std::make_unique<EnergyBalance>(*model_, initial, body_resultants(*model_, initial), rate_independent());
  ode.resume(resume_->state, resume_->step, resume_->progress.solves, resume_->excursion, resume_->springs_beta);
  body_ = body_resultants(*model_, resume_->state);
  energy_->resume(resume_->state, body_, resume_->energy);
  const RunResult& p = resume_->progress;
  result_.snapshots = p.snapshots;
  if (writer_) result_.steps = writer_->resumed_steps();  // processes other than 0 write nothing (la/parallel.hpp)
  result_.restarted_at = resume_->state.t;
  result_.solves_before_restart = p.solves;
  rows_step_ = resume_->step;
  notes_ = resume_->notes;
  result_.peak_force = p.peak_force;
  result_.peak_time = p.peak_time;
  earlier_ = p.integrator;
}

double Recorder::initial_step() const { return resume_ ? resume_->last_step : 0.0; }

void Recorder::attach(BetaIntegrator& integrator) {
  integrator_ = &integrator;
  if (resume_) integrator.restore(resume_->diagnostics);
}

const BodyState& Recorder::fields() {
  if (body_.u.size() != 0) return body_;
  const double start = seconds();
  body_ = body_state(*model_, ode_->committed());
  ++result_.body_solves;
  result_.body_solve_seconds += seconds() - start;
  return body_;
}

void Recorder::step(const AcceptedStep& a) {
  body_ = body_resultants(*model_, a.state);
  if (!energy_) {
    energy_ = std::make_unique<EnergyBalance>(*model_, a.state, body_, rate_independent());
  } else if (a.midpoint) {
    const BodyState mid_body = body_resultants(*model_, *a.midpoint);
    energy_->add(a.state, body_, a.midpoint, &mid_body);
  } else {
    energy_->add(a.state, body_);
  }
  result_.peak_force.resize(body_.force.size(), 0.0);
  result_.peak_time.resize(body_.force.size(), 0.0);
  for (std::size_t k = 0; k < body_.force.size(); ++k)
    if (std::abs(body_.force[k]) > std::abs(result_.peak_force[k]))
      result_.peak_force[k] = body_.force[k], result_.peak_time[k] = a.t;
  result_.steps.push_back({a.step, a.t, a.dt, a.counts.contact_solves, a.counts.sweeps_per_solve(),
                           a.counts.max_sweeps, a.wall_seconds});
  if (writer_) writer_->step(a, body_, energy_->terms());
  rows_step_ = a.step;  // its rows are written: a checkpoint may now stand at it
  if (a.step == 0 || (cfg_.output.every > 0 && a.step % cfg_.output.every == 0)) {
    const BodyState& b = fields();  // a solve of the body: every process joins it (la/parallel.hpp)
    if (writer_) writer_->frame(a.state, b);
  }
  if (options_.step_log) log_step(*options_.step_log, a);
  if (options_.progress) progress_line(a, cfg_.time.T);
  note_crawl(a);
  note_deformation(a);  // before a checkpoint of this step: it keeps what the step said
  if (writer_ && integrator_ && cfg_.output.checkpoint_steps > 0 && a.step % cfg_.output.checkpoint_steps == 0)
    save_checkpoint();
  if (options_.observer) options_.observer(a);
}

void Recorder::note_crawl(const AcceptedStep& a) {
  // A run whose steps stay tiny says so once, while it runs, instead of crawling silently.
  tiny_steps_ = a.dt > 0 && a.dt < 1e-7 * cfg_.time.T ? tiny_steps_ + 1 : 0;
  if (tiny_steps_ != 100) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "t = %g s: 100 accepted steps in a row below 1e-7 T (dt = %.3g s): the run crawls; if it does not pass, "
                "loosen integrator.rtol, raise integrator.min_step, or look for extreme interface values "
                "(interface.Cn, Ct, mu)",
                a.t, a.dt);
  note(text);
}

void Recorder::note_deformation(const AcceptedStep& a) {
  // Linear elasticity assumes small displacement gradients: a run driven far beyond them
  // (a coating lifted by tens of mm and turned by tens of degrees) says so once. A fraction
  // of the bodies, not one cell: the cells under a point load or at a crack tip exceed any
  // limit as the mesh is refined. Checked every T / deformation_checks of time and at T:
  // at every step it cost 3 % of B1 x16's run. Also checked wherever the body is solved anyway
  // (a frame, an output time, T); the checks due in between are left out while the solves took
  // more than their share of the run.
  if (notes_.deformation_noted) return;
  bool solved = body_.u.size() != 0;
  for (double t_out : stops_) solved = solved || std::abs(a.t - t_out) <= 1e-12 * cfg_.time.T;
  if (!solved && a.t < notes_.deformation_checked + cfg_.time.T / deformation_checks) return;
  notes_.deformation_checked = a.t;
  // Each process's clock differs: under mpirun all leave the check out if one would, so that
  // all join the check's solve or none does.
  if (!solved && parallel::largest(result_.body_solve_seconds >
                                   options_.strain_check_share * (seconds() - result_.setup_seconds))) {
    ++result_.strain_checks_left_out;
    return;
  }
  ++result_.strain_checks;
  const DeformationExcess e = (*small_strains_)(fields().u, small_strain_limit);
  if (e.fraction <= small_strain_fraction) return;
  notes_.deformation_noted = true;
  const Mesh& mesh = model_->mesh();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int n : mesh.cells[e.cell]) centre += mesh.nodes[n] / double(mesh.cells[e.cell].size());
  char text[600];
  std::snprintf(text, sizeof text,
                "t = %g s: the displacement gradient |grad u| exceeds %g over %.1f %% of body '%s' (at most %.3f, at "
                "%s): beyond the small strains and rotations of linear elasticity (a rotation by %g rad alone strains "
                "a linear model by %.2g), its stresses and forces there are not to be trusted; lower the load or read "
                "the run as qualitative",
                a.t, small_strain_limit, 100 * e.fraction, mesh.body_names[e.body].c_str(), e.largest,
                point(centre, mesh.dim).c_str(), small_strain_limit, 1 - std::cos(small_strain_limit));
  note(text);
}

void Recorder::note(const std::string& text) {
  notes_.said.push_back(text);
  if (options_.write_files) say_note(text, options_.progress ? "\n" : "");
}

void Recorder::say_note(const std::string& text, const char* lead) const {
  std::fprintf(stderr, "%srccm: %s%snote: %s\n", lead, options_.label.c_str(), options_.label.empty() ? "" : ": ",
               text.c_str());
}

void Recorder::save_checkpoint() {
  Checkpoint c{cfg_.settings,           cfg_.settings_parts,        ode_->steps(),              integrator_->last_step(), ode_->committed(),
               energy_->terms(),        integrator_->diagnostics(), ode_->excursion(),        {}, {},
               model_->springs_beta(),  notes_};
  c.progress.snapshots = result_.snapshots;
  c.progress.peak_force = result_.peak_force;
  c.progress.peak_time = result_.peak_time;
  c.progress.solves = ode_->totals();
  c.progress.integrator = earlier_ + integrator_->stats();
  c.progress.integrator.steps = ode_->steps();  // also inside a step, before the scheme counts it
  for (const ContactPair& pair : model_->interface().pairs) c.contact_nodes.push_back(pair.node);
  write_checkpoint(writer_->directory(), c);
}

bool Recorder::has_snapshot(double t_out) const {
  return !result_.snapshots.empty() && result_.snapshots.back().t >= t_out - 1e-12 * cfg_.time.T;
}

void Recorder::snapshot() {
  const InterfaceState& s = ode_->committed();
  result_.snapshots.push_back({s.t, s.beta, s.Rbar, s.u, debonded_length(*model_, s.beta)});
  const BodyState& b = fields();  // the last accepted step is the one at s.t; every process joins its solve
  if (writer_) writer_->output(s, b);
}

RunResult Recorder::finish() { return close(""); }

std::string Recorder::stop(const std::string& why) {
  if (!ode_ || !integrator_) return "";
  try {
    close(why);
  } catch (const std::exception& e) {
    return "\n  the report could not be written (" + std::string(e.what()) + "); the CSV files hold every step "
           "written before";
  }
  if (!writer_) return "";
  const bool restartable = std::filesystem::exists(checkpoint_path(writer_->directory()));
  return "\n  the results up to the last accepted step (t = " + csv_number(ode_->committed().t) + " s) are in " +
         writer_->directory() + "; report.txt says where the run stopped, " +
         (restartable ? "checkpoint.txt restarts it (--restart)" : "and no checkpoint was written: run it afresh");
}

RunResult Recorder::close(const std::string& stopped) {
  // The restart point: the last accepted state, before a stopped run's extra snapshot of it;
  // not a state whose rows failed to be written (a full disk): the CSVs would end before it
  // and refuse the restart, where the last checkpoint's state is still a good one.
  if (writer_ && rows_step_ == ode_->steps()) save_checkpoint();
  result_.stopped = stopped;
  if (!stopped.empty() && (result_.snapshots.empty() || result_.snapshots.back().t < ode_->committed().t)) snapshot();
  if (options_.progress) std::fputs("\n", stderr);
  result_.integrator = earlier_ + integrator_->stats();
  // The accepted steps as the files hold them: a stop asked at a step ends the run inside the
  // integrator's step, before it counts it.
  result_.integrator.steps = ode_->steps();
  result_.solves = ode_->totals();
  result_.energy = energy_->terms();
  result_.warnings = model_->notes();
  for (const std::string& w : integrator_->warnings()) result_.warnings.push_back(w);
  result_.warnings.insert(result_.warnings.end(), notes_.said.begin(), notes_.said.end());
  for (const std::string& w : ode_->warnings()) result_.warnings.push_back(w);
  result_.wall_seconds = seconds();
  if (writer_) write_reports(writer_->directory(), cfg_, result_);
  return result_;
}

}  // namespace rccm
