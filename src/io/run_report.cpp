#include "rccm/io/run_report.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/format.hpp"
#include "rccm/io/atomic_file.hpp"
#include "rccm/la/blas_threads.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>

namespace rccm {

std::vector<PaperColumn> paper_table_columns(const Config& cfg, const RunResult& r, int last) {
  std::vector<PaperColumn> cols;
  if (r.steps.size() < 2) return cols;
  const bool grid = cfg.integrator.method != Method::Arkode;
  const int N = grid ? cfg.time.steps : static_cast<int>(r.steps.size()) - 1;
  last = std::min(last, N);
  if (grid)  // a run stopped early: the grid's steps it completed
    last = std::min(last, static_cast<int>(std::floor(r.steps.back().t / cfg.time.T * N + 1e-6)));
  for (int want : {1, 10, 40, 60, 100, 150, 200}) {
    const int k = std::min(want, last);
    if (!cols.empty() && cols.back().step == k) continue;
    const StepRecord* s = &r.steps[k];  // ARKODE: the k-th accepted step (k <= last <= the steps recorded)
    if (grid) {  // the accepted step that ends nearest to k T / N (the grid's own step ends there)
      const double t = cfg.time.T * k / N;
      s = &*std::min_element(r.steps.begin(), r.steps.end(), [t](const StepRecord& a, const StepRecord& b) {
        return std::abs(a.t - t) < std::abs(b.t - t);
      });
    }
    cols.push_back({k, s});
  }
  return cols;
}

void write_report_text(std::ostream& out, const Config& cfg, const RunResult& r) {
  out << "rccm run report: " << cfg.file << "\n"
      << "mesh: " << r.nodes << " nodes, " << r.cells << " cells, " << r.dofs << " DOFs, " << r.contact_nodes
      << " contact nodes\n"
      << "body's solves: " << r.linear_solver << "\n"
      << "interface flexibility W0: " << r.flexibility << "\n";
  if (const StateSlices& s = r.integrator.slices; s.processes > 0)
    out << "beta (ARKODE's state) distributed over " << s.processes << " processes: " << s.smallest << " to "
        << s.largest << " contact pairs each, " << s.pairs << " in all\n";
  const bool solid = cfg.mesh.dim() == 3;
  out << "bodies (" << (solid ? "3D" : hypothesis_name(cfg.hypothesis())) << "):";
  for (const std::string& b : r.bodies) out << " " << b;
  out << "\ninterfaces:";
  for (std::size_t k = 0; k < cfg.interfaces.size() && k < r.pairs_per_interface.size(); ++k) {
    const InterfaceParams& p = cfg.interfaces[k];
    out << (k ? ";" : "") << " " << p.path << " '" << p.boundary << "' against "
        << (p.facing == Facing::Line     ? (solid ? "a rigid plane" : "a rigid line")
            : p.facing == Facing::Circle ? (!solid ? "a rigid circle" : p.axis == std::array<double, 3>{} ? "a rigid sphere" : "a rigid cylinder")
                                         : "'" + p.opposite + "'")
        << " (" << r.pairs_per_interface[k] << " pairs)";
  }
  out << "\nintegrator: " << method_name(cfg.integrator.method);
  if (cfg.integrator.method == Method::Arkode)
    out << " (" << (cfg.integrator.scheme == ArkodeScheme::Dirk ? "dirk" : "erk") << ", rtol " << cfg.integrator.rtol
        << ", atol " << cfg.integrator.atol << ")";
  if (cfg.integrator.method == Method::ContactOnly)
    out << " (beta held at beta0)";
  else
    for (const InterfaceParams& p : cfg.interfaces) out << "; " << p.path << ".alpha = " << p.alpha << " N s/mm";
  out << "\n";
  if (r.stopped.empty())
    out << "status: complete (t = " << cfg.time.T << " s)\n\n";
  else
    out << "status: STOPPED before T = " << cfg.time.T << " s, at the last accepted step t = "
        << (r.snapshots.empty() ? 0.0 : r.snapshots.back().t) << " s (its interface and mesh are written)\n  "
        << r.stopped << "\n\n";

  out << "Work per step (the paper's Table 1 layout)\n";
  const auto cols = paper_table_columns(cfg, r);
  auto row = [&](const char* label, auto value) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%-30s", label);
    out << buf;
    for (const PaperColumn& c : cols) out << value(c);
    out << "\n";
  };
  row("step", [](const PaperColumn& c) { return fmt("%10.0f", c.step); });
  row("t [s]", [](const PaperColumn& c) { return fmt("%10.4f", c.record->t); });
  row("contact solves (beta iter.)", [](const PaperColumn& c) { return fmt("%10.0f", c.record->contact_solves); });
  row("contact iterations per solve", [](const PaperColumn& c) { return fmt("%10.2f", c.record->sweeps_mean); });
  row("wall [s] (the paper: CPU)", [](const PaperColumn& c) { return fmt("%10.2e", c.record->wall_seconds); });

  const IntegratorStats& I = r.integrator;
  const SolveCounts own = solves_of_this_process(r);  // beside the wall time, since a restart
  out << "\nTotals\n"
      << "  accepted steps          " << I.steps << " (" << I.rejected << " rejected)\n"
      << "  RHS evaluations         " << I.rhs_evaluations << "\n"
      << "  Newton / fixed-point it " << I.newton_iterations << "\n"
      << "  contact solves          " << r.solves.contact_solves << "\n"
      << "  contact iterations      " << fmt("%.2f", double(r.solves.sweeps) / std::max(1L, r.solves.contact_solves))
      << " per solve, max " << r.solves.max_sweeps << "\n"
      << [&] {
           const std::string line = threaded_sweeps_line(r.solves, blas_threads::most_products());
           return line.empty() ? line : "  " + line + "\n";
         }()
      << (cfg.solver.springs_follow_beta ? "  W0's springs followed   " + std::to_string(r.solves.condensations) + " times (" +
                                               fmt("%.3f", r.solves.condense_seconds) + " s; solver.springs_follow_beta)\n"
                                         : std::string())
      << "  wall time               " << fmt("%.3f", r.wall_seconds) << " s (setup " << fmt("%.4f", r.setup_seconds)
      << " s)" << (r.restarted_at >= 0 ? " since the restart at t = " + fmt("%g", r.restarted_at) + " s" : "") << "\n"
      << "  of it: contact solves   " << fmt("%.3f", own.seconds) << " s ("
      << fmt("%.3g", 1e3 * own.seconds / double(std::max(1L, own.contact_solves))) << " ms each), "
      << r.body_solves << " solves of the body " << fmt("%.3f", r.body_solve_seconds) << " s\n"
      << "  small-strain checks     " << r.strain_checks
      << (r.strain_checks_left_out ? " (" + std::to_string(r.strain_checks_left_out) +
                                         " left out: their solves of the body would have passed a tenth of the run)"
                                   : std::string())
      << "\n";

  const EnergyTerms& e = r.energy;
  const bool rate_independent = cfg.integrator.method == Method::RateIndependent;
  out << "\nEnergy balance at T (docs/MODEL.md s3), N mm "
      << (cfg.hypothesis() == Hypothesis::Axisymmetric ? "(the whole body of revolution)"
          : solid                                      ? "(the whole body)"
                                                       : "per mm of thickness")
      << "\n"
      << "  external work                  " << fmt("%.8e", e.external_work) << "\n"
      << "  strain energy                  " << fmt("%.8e", e.strain_energy) << "\n"
      << "  interface free energy change   " << fmt("%.8e", e.free_energy_change) << "\n"
      << "  damage dissipation             " << fmt("%.8e", e.damage_dissipation) << "\n"
      << "  friction dissipation           " << fmt("%.8e", e.friction_dissipation) << "\n"
      << (rate_independent ? "  snap-through and step error    " : "  imbalance                      ")
      << fmt("%.3e", e.imbalance()) << " (relative " << fmt("%.3e", e.relative_error()) << ")\n"
      << "  normal contact work (0 exact)  " << fmt("%.3e", e.normal_contact_work) << "\n";
  if (rate_independent) {
    out << "  In the rate-independent limit beta jumps within a step where the interface snaps through: the\n"
           "  work released there is no dissipation of the law (alpha beta'^2 with alpha = 0), and the balance\n"
           "  leaves it beside the steps' own error (the trapezoid rule, shrinking like dt^2; docs/MODEL.md\n"
           "  s3). What a snap-through releases does not shrink with the steps: twice time.steps tells the\n"
           "  two apart. The normal contact work, 0 along an exact path, is the trapezoid rule across a jump.\n";
    if (e.imbalance() < -e.round_off)  // a snap-through releases work, it never takes any in
      out << "  It is negative here: no snap-through releases negative work, so the steps' error is at\n"
             "  least this large; more time.steps make it smaller.\n";
  } else if (e.relative_error() > 1e-2)
    out << "  The imbalance is large: beta fell by a large amount within single steps (a time step too\n"
           "  coarse for the debonding); refine the steps or tighten integrator.rtol.\n";
  for (const std::string& w : r.warnings) out << "\nwarning: " << w << "\n";
}

std::string threaded_sweeps_line(const SolveCounts& solves, int most_threads) {
  if (solves.timed_sweeps == 0 || most_threads < 2) return {};
  return "sweeps in " + std::to_string(most_threads) + " threads: " + std::to_string(solves.threaded_sweeps) +
         " of the compressed W0's " + std::to_string(solves.timed_sweeps) +
         " (the others in one: the timings' probes, and all where one was faster: other work on the cores)";
}

void write_report_json(std::ostream& out, const Config& cfg, const RunResult& r) {
  const EnergyTerms& e = r.energy;
  const IntegratorStats& I = r.integrator;
  using nlohmann::json;
  json alpha = json::array();
  for (const InterfaceParams& p : cfg.interfaces) alpha.push_back(p.alpha);
  json energy = {{"external_work", e.external_work},           {"strain_energy", e.strain_energy},
                 {"free_energy_change", e.free_energy_change}, {"damage_dissipation", e.damage_dissipation},
                 {"friction_dissipation", e.friction_dissipation}, {"normal_contact_work", e.normal_contact_work},
                 {"relative_error", e.relative_error()},           {"round_off", e.round_off}};
  // In the rate-independent limit the balance leaves what snap-throughs release and the steps' error.
  energy[cfg.integrator.method == Method::RateIndependent ? "snap_through_and_step_error" : "imbalance"] = e.imbalance();
  json steps = json::array();
  for (const StepRecord& s : r.steps)
    steps.push_back({{"step", s.step},
                     {"t", s.t},
                     {"dt", s.dt},
                     {"contact_solves", s.contact_solves},
                     {"sweeps_mean", s.sweeps_mean},
                     {"sweeps_max", s.sweeps_max},
                     {"wall_seconds", s.wall_seconds}});
  json snapshots = json::array();
  for (const Snapshot& s : r.snapshots) snapshots.push_back({{"t", s.t}, {"debonded_length", s.debonded_length}});
  const json report = {{"config", cfg.file},
                       {"hypothesis", cfg.mesh.dim() == 3 ? "3D" : hypothesis_name(cfg.hypothesis())},
                       {"rccm_version", RCCM_VERSION_STRING},
                       {"integrator", method_name(cfg.integrator.method)},
                       {"alpha", alpha},
                       {"nodes", r.nodes},
                       {"cells", r.cells},
                       {"dofs", r.dofs},
                       {"contact_nodes", r.contact_nodes},
                       {"linear_solver", r.linear_solver},
                       {"flexibility", r.flexibility},
                       {"beta_slices", I.slices.processes == 0 ? json(nullptr)
                                                               : json{{"processes", I.slices.processes},
                                                                      {"smallest", I.slices.smallest},
                                                                      {"largest", I.slices.largest},
                                                                      {"pairs", I.slices.pairs}}},
                       {"bodies", r.bodies},
                       {"pairs_per_interface", r.pairs_per_interface},
                       {"steps", I.steps},
                       {"rejected_steps", I.rejected},
                       {"rhs_evaluations", I.rhs_evaluations},
                       {"newton_iterations", I.newton_iterations},
                       {"contact_solves", r.solves.contact_solves},
                       {"sweeps_per_solve", r.solves.sweeps_per_solve()},
                       {"sweeps_max", r.solves.max_sweeps},
                       {"condensations", r.solves.condensations},
                       {"condense_seconds", r.solves.condense_seconds},
                       {"contact_solve_seconds", r.solves.seconds},
                       {"sweeps_compressed", r.solves.timed_sweeps},
                       {"sweeps_threaded", r.solves.threaded_sweeps},
                       {"body_solves", r.body_solves},
                       {"body_solve_seconds", r.body_solve_seconds},
                       {"strain_checks", r.strain_checks},
                       {"strain_checks_left_out", r.strain_checks_left_out},
                       {"wall_seconds", r.wall_seconds},
                       {"restarted_at", r.restarted_at},
                       {"setup_seconds", r.setup_seconds},
                       {"energy", energy},
                       {"peak_force", r.peak_force},
                       {"peak_time", r.peak_time},
                       {"snapshots", snapshots},
                       {"per_step", steps},
                       {"complete", r.stopped.empty()},
                       {"stopped", r.stopped},
                       {"warnings", r.warnings},
                       {"settings", cfg.fingerprint()},
                       {"settings_parts", cfg.fingerprint_parts()},
                       {"controls", cfg.controls_fingerprint()}};
  // Numbers to 17 significant digits (nlohmann writes the shortest exact form), strings escaped.
  out << report.dump(2) << "\n";
}

ReportedRun read_report_json(const std::string& directory, const Config& cfg) {
  const std::string path = directory + "/report.json";
  std::ifstream in(path);
  const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  if (!in || report.is_discarded() || !report.is_object())
    throw InputError(path + ": cannot be read as the report of a run (damaged?)");
  if (report.value("settings", std::string()) != cfg.fingerprint()) {
    const std::string names = differing_settings(report.value("settings_parts", std::string()), cfg.fingerprint_parts());
    throw InputError(path + ": a run of other settings than " + cfg.file + " with this case's --set" +
                     (names.empty() ? " (or of another mesh file, or written by another version of rccm)" : " (" + names + ")"));
  }
  try {
    if (!report.at("complete").get<bool>())
      throw InputError(path + ": the report of a run that did not complete, beside a report.txt that says it did (a "
                       "run cut off while writing them?)");
    RunResult r;
    r.stopped = report.at("stopped").get<std::string>();
    const nlohmann::json& e = report.at("energy");
    r.energy = {e.at("external_work"),        e.at("strain_energy"),        e.at("free_energy_change"),
                e.at("damage_dissipation"),   e.at("friction_dissipation"), e.at("normal_contact_work"),
                e.value("round_off", 0.0)};
    r.peak_force = report.at("peak_force").get<std::vector<double>>();
    r.peak_time = report.at("peak_time").get<std::vector<double>>();
    for (const nlohmann::json& s : report.at("snapshots")) {
      r.snapshots.emplace_back();
      r.snapshots.back().t = s.at("t");
      r.snapshots.back().debonded_length = s.at("debonded_length");
    }
    r.integrator.steps = report.at("steps");
    r.integrator.rejected = report.at("rejected_steps");
    r.solves.contact_solves = report.at("contact_solves");
    r.wall_seconds = report.at("wall_seconds");
    r.setup_seconds = report.at("setup_seconds");
    r.restarted_at = report.at("restarted_at");
    r.warnings = report.at("warnings").get<std::vector<std::string>>();
    return {r, report.value("controls", std::string()) == cfg.controls_fingerprint()};
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": not the report of a run of this rccm (" + e.what() + ")");
  }
}

void write_reports(const std::string& directory, const Config& cfg, const RunResult& r) {
  AtomicFile txt(directory + "/report.txt"), json(directory + "/report.json");
  write_report_text(txt.stream(), cfg, r);
  write_report_json(json.stream(), cfg, r);
  json.commit();  // report.txt last: its "status: complete" marks a finished run (holds_complete_run)
  txt.commit();
}

}  // namespace rccm
