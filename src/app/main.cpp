// rccm: quasi-static FE contact with the RCCM interface law, solved by the bipotential method.
// Exit status: 0 success, 2 bad input (nothing written), 3 a run that failed, 128 + signal a
// run stopped by SIGINT/SIGTERM, 1 an internal error.
#include "rccm/app/bench.hpp"
#include "rccm/app/compare.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/app/stop_request.hpp"
#include "rccm/app/sweep.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/base/suggest.hpp"
#include "rccm/io/config_reader.hpp"
#include "rccm/io/output_directory.hpp"
#include "rccm/io/run_report.hpp"
#include "rccm/la/blas_threads.hpp"
#include "rccm/la/parallel.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <thread>
#include <unistd.h>

namespace {

/// A line to stderr in one write: under mpirun another process's abort notice otherwise landed
/// inside it (seen: between "rccm: run failed: " and ARKODE's message, which a test looks for).
void say(const std::string& line) { std::cerr << line + "\n"; }

void print_totals(const rccm::RunResult& r) {
  // Times of this process (a restart's since it restarted), counts of the whole run.
  const rccm::SolveCounts own = rccm::solves_of_this_process(r);
  std::printf("# %ld steps (%ld rejected), %ld contact solves, %.2f sweeps per solve (max %d)\n"
              "# wall %.3f s%s: setup %.4f s, contact solves %.3f s (%.1f us each)\n",
              r.integrator.steps, r.integrator.rejected, r.solves.contact_solves, r.solves.sweeps_per_solve(),
              r.solves.max_sweeps, r.wall_seconds, r.restarted_at >= 0 ? " since the restart" : "", r.setup_seconds,
              own.seconds, 1e6 * own.seconds / double(std::max(1L, own.contact_solves)));
  const std::string threaded = rccm::threaded_sweeps_line(r.solves, rccm::blas_threads::most_products());
  if (!threaded.empty()) std::printf("# %s\n", threaded.c_str());
  if (r.solves.condensations > 0)
    std::printf("# W0's springs followed beta %ld times (%.3f s of the wall time)\n", r.solves.condensations,
                r.solves.condense_seconds);
  for (const std::string& w : r.warnings) std::cerr << "rccm: warning: " << w << "\n";
}

/// `rccm sweep`: the cases, run in parallel; the exit status of the worst case.
int sweep(const std::string& config_file, const std::vector<std::string>& overrides, std::string directory, int jobs,
          bool force, bool resume, const char* rccm_path) {
  std::vector<rccm::SweepAxis> axes;
  std::vector<std::string> fixed;
  rccm::split_sweep_settings(overrides, axes, fixed);
  if (axes.empty())
    throw rccm::InputError("sweep: give at least one list, e.g. --set interface.alpha=0,0.01,0.1,1,10,100");
  const rccm::Config cfg = rccm::load_config(config_file, fixed);
  if (!std::filesystem::is_regular_file(config_file))  // read once above, and drained
    throw rccm::InputError("sweep: " + config_file + " is a pipe: a sweep reads its config for every case, and its "
                           "jobs.txt runs it again; give a file");
  if (directory.empty()) directory = cfg.output.directory + "-sweep";
  std::vector<rccm::SweepCase> cases = rccm::make_sweep_cases(config_file, fixed, axes, directory);
  if (resume && !std::filesystem::is_directory(directory))
    throw rccm::InputError("sweep --restart " + directory + ": no such directory (the directory of the sweep to go on with)");
  std::optional<rccm::DirectoryLock> lock;  // one sweep at a time in the directory (its summary, its cases)
  if (resume) {  // each case as its directory says: kept, restarted or run
    lock.emplace(directory, "sweep --restart");
    for (const std::string& note : rccm::plan_resumed_sweep(cases)) std::cout << "# " << note << "\n";
  }
  if (!resume && !force) {  // as `rccm run`: a sweep's or a case's results are not overwritten, and nothing is written
    for (const rccm::SweepCase& c : cases) {
      try {
        rccm::check_output_directory(c.config, false);
      } catch (const rccm::InputError& e) {
        throw rccm::InputError("sweep: case " + c.name + ": " + e.what() + " (--restart " + directory +
                               " goes on with the sweep: its complete cases kept, its stopped ones restarted; "
                               "--force runs the whole sweep afresh)");
      }
    }
    for (const char* file : {"summary.csv", "jobs.txt"})  // another sweep's (its cases need not clash)
      if (std::filesystem::exists(std::filesystem::path(directory) / file))
        throw rccm::InputError("sweep: " + directory + " holds the " + file + " of an earlier sweep: give another "
                               "--output, --restart " + directory + " to go on with that sweep, or --force to run "
                               "this one afresh there (its summary replaces the earlier one)");
  }
  for (const rccm::SweepCase& c : cases)  // PETSc is not thread-safe: its cases one at a time
    if (jobs > 1 && (c.config.solver.linear.kind == rccm::LinearSolver::Mumps ||
                     c.config.solver.linear.kind == rccm::LinearSolver::CgGamg))
      throw rccm::InputError("sweep: case " + c.name + " solves the body with PETSc (solver.linear), which runs one "
                             "case at a time: give -j 1");
  std::filesystem::create_directories(directory);
  if (!lock) lock.emplace(directory, "sweep");
  std::cout << "# " << cases.size() << " cases on " << jobs << (jobs == 1 ? " thread" : " threads") << ", in " << directory << "\n";
  if (jobs > 1) rccm::blas_threads::keep_one();  // the cases' wide scopes would set the BLAS's threads for each other
  if (force) std::filesystem::remove(std::filesystem::path(directory) / "summary.csv");  // not beside the new job list
  rccm::write_sweep_jobs(directory, cases, rccm_path, config_file);
  rccm::run_sweep(cases, jobs, force);
  rccm::write_sweep_summary(std::cout, directory, axes, cases);
  const std::string overlay = rccm::overlay_command(directory, cases);
  std::cout << "# " << directory << "/summary.csv, " << directory << "/jobs.txt; plots: "
            << (overlay.empty() ? "none (no case has results)" : overlay) << "\n";
  int status = 0;
  for (const rccm::SweepCase& c : cases) {
    if (c.status == rccm::CaseStatus::Interrupted || c.status == rccm::CaseStatus::NotRun) {
      std::cerr << "rccm: sweep stopped by a signal; cases not run are marked 'not run' in summary.csv; to go on: "
                << rccm::resume_command(rccm_path, config_file, overrides, jobs, directory) << "\n";
      return 128 + rccm::stop_signal();
    }
    if (c.status == rccm::CaseStatus::Failed) status = 3;
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rccm " RCCM_VERSION_STRING ": RCCM interface (contact, Coulomb friction, adhesion) by the bipotential method"};
  app.set_version_flag("--version", "rccm " RCCM_VERSION_STRING);
  app.require_subcommand(1);
  std::string config_file, output_dir;
  std::vector<std::string> overrides, integrators{"arkode", "euler"}, solvers;
  bool quiet = false;
  int euler_steps = 0;

  CLI::App* run = app.add_subcommand("run", "run the problem of a config file");
  CLI::App* compare =
      app.add_subcommand("compare", "run one problem with several integrators and contact solvers, side by side");
  CLI::App* sweep_app = app.add_subcommand(
      "sweep", "run a config for every value of listed settings (--set interface.alpha=0,0.1,1,10), in parallel");
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  sweep_app->add_option("--jobs,-j", jobs, "cases run at once (default: the machine's cores)")
      ->check(CLI::Range(1, 1024));
  CLI::Option* sweep_output = sweep_app->add_option("--output,-o", output_dir,
                                                   "directory of the cases and the summary (default: <output.directory>-sweep)");
  CLI::Option* run_output = run->add_option("--output,-o", output_dir, "output directory (instead of output.directory)");
  for (CLI::App* sub : {run, compare, sweep_app}) {
    sub->add_option("config", config_file, "libconfig file, e.g. config/b1.cfg")->required();
    sub->add_option("--set", overrides, "override a setting: path=value (repeatable)");
  }
  CLI::App* bench = app.add_subcommand(
      "bench", "time B1 and B2 with each integrator against the paper's totals; --scale: the refined B1 family; "
               "--scale3d: the 3D corner peel family");
  std::string bench_dir = "config", bench_csv, bench_json;
  int scale_levels = 0;
  double scale_time = 1.0;
  bench->add_option("--config-dir", bench_dir, "where b1.cfg and b2.cfg are (default: config)");
  bench->add_option("--csv", bench_csv, "also write the table as CSV");
  bench->add_option("--json", bench_json, "also write the table as JSON");
  bench->add_option("--scale", scale_levels, "refined B1 family: levels 1x, 2x, 4x, ... cells in each direction")
      ->check(CLI::Range(0, 12));
  int scale3d_levels = 0;
  bench->add_option("--scale3d", scale3d_levels, "the 3D corner peel on 8, 12, 16, 24, 32, 45, 64 cells a side: the first N")
      ->check(CLI::Range(0, 7));
  bench->add_option("--scale-time", scale_time, "simulated time of each scale case, s (default 1)")
      ->check(CLI::Validator([](const std::string& v) { return std::strtod(v.c_str(), nullptr) > 0 ? "" : "must be > 0 (got " + v + ")"; }, "> 0"));
  std::string bench_linear = "auto";
  const std::map<std::string, rccm::LinearSolver> linear_solvers{{"auto", rccm::LinearSolver::Auto},
                                                                  {"cholmod", rccm::LinearSolver::Cholmod},
                                                                  {"mumps", rccm::LinearSolver::Mumps},
                                                                  {"cg-gamg", rccm::LinearSolver::CgGamg}};
  bench->add_option("--linear", bench_linear, "the body's solver of the scale cases (solver.linear; default auto)")
      ->check(CLI::IsMember(linear_solvers));
  bool verbose = false, force = false;
  run->add_flag("--quiet,-q", quiet, "no progress line");
  for (CLI::App* sub : {run, sweep_app})
    sub->add_flag("--force", force, "start afresh over the results of an earlier run in the output directory");
  run->add_flag("--verbose,-v", verbose, "one line per accepted step on stdout");
  std::string restart_dir;
  CLI::Option* restart = run->add_option(
      "--restart", restart_dir, "go on from the checkpoint of an interrupted or failed run of the same config in DIR");
  restart->excludes("--force");
  CLI::Option* sweep_restart = sweep_app->add_option(
      "--restart", restart_dir,
      "go on with the interrupted sweep in DIR (same config and --set): complete cases kept, stopped ones restarted");
  sweep_restart->excludes("--force");
  compare->add_option("--integrators", integrators, "comma-separated: arkode, euler, rate-independent, contact-only")
      ->delimiter(',');
  compare->add_option("--solvers", solvers, "comma-separated: bipotential, rccm, newton (default: solver.method)")
      ->delimiter(',');
  compare->add_option("--euler-steps", euler_steps, "fixed steps of the euler case (default: time.steps)")
      ->check(CLI::Range(1, 100000000));

  // A mistyped command (`rccm runn`) named, where CLI11 would say only that one is required.
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
    if (std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
      std::cerr << "rccm: error: '" << argv[1] << "' is not a command" << rccm::suggestion(argv[1], commands)
                << " (rccm --help lists them)\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  // A closed pipe (rccm run -v | head) fails the write, not the run: the files stay complete.
  std::signal(SIGPIPE, SIG_IGN);
  // rccm waits for rccm-gmsh: a SIGCHLD ignored by whoever started rccm would reap it first.
  std::signal(SIGCHLD, SIG_DFL);
  // Under mpirun: every process runs the problem, the body's solves are shared, process 0 writes.
  if (rccm::parallel::launched()) rccm::parallel::start();
  // The BLAS: one thread outside the large sparse work, whose idle threads would spin on the
  // other cores (la/blas_threads.hpp); one everywhere when processes share the cores.
  rccm::blas_threads::start();
  if (rccm::parallel::size() > 1) rccm::blas_threads::keep_one();
  const bool root = rccm::parallel::rank() == 0;
  const int status = [&] {
  try {
    if (rccm::parallel::size() > 1 && !*run && !*bench)
      throw rccm::InputError("under mpirun only `rccm run` and `rccm bench` share their work among processes; run `rccm " +
                             app.get_subcommands().front()->get_name() + "` as one process");
    if (*bench) {
      const rccm::LinearSolver linear = linear_solvers.at(bench_linear);
      if (root && !bench_csv.empty()) rccm::check_output_file(bench_csv, "bench --csv");  // before the minutes of the cases
      if (root && !bench_json.empty()) rccm::check_output_file(bench_json, "bench --json");  // (process 0 writes them)
      if ((scale_levels > 0 || scale3d_levels > 0) && linear == rccm::LinearSolver::Cholmod && rccm::parallel::size() > 1)
        throw rccm::InputError("bench --linear cholmod solves in one process; under mpirun use mumps or cg-gamg");
      std::ostream nowhere(nullptr);  // every process runs the cases, process 0 prints
      std::ostream& out = root ? std::cout : nowhere;
      std::vector<rccm::BenchRow> rows;
      rccm::print_bench_header(out);
      for (const rccm::BenchCase& c : rccm::paper_cases(bench_dir)) {
        rows.push_back(rccm::run_bench_case(c));
        rccm::print_bench_row(out, rows.back());
      }
      // A family of growing cases: its table, the body's solver and the growth exponents.
      const auto family = [&](const std::string& title, const std::vector<rccm::BenchCase>& cases) {
        if (cases.empty()) return;
        std::vector<rccm::BenchRow> scale;
        out << "\n# " << title << ", t in [0, " << scale_time << "] s\n";
        rccm::print_bench_header(out);
        for (const rccm::BenchCase& c : cases) {
          scale.push_back(rccm::run_bench_case(c));
          rccm::print_bench_row(out, scale.back());
        }
        out << "# body's solves: " << scale.back().result.linear_solver << "\n";
        rccm::print_growth(out, scale);
        rows.insert(rows.end(), scale.begin(), scale.end());
      };
      family("refined B1", rccm::scale_cases(bench_dir, scale_levels, scale_time, linear));
      family("3D corner peel", rccm::corner_peel_cases(bench_dir, scale3d_levels, scale_time, linear));
      if (root && !bench_csv.empty()) rccm::write_bench_csv(bench_csv, rows);
      if (root && !bench_json.empty()) rccm::write_bench_json(bench_json, rows);
      return 0;
    }
    if (restart->count() + sweep_restart->count() > 0 && restart_dir.empty())
      throw rccm::InputError("--restart: give the directory of the run to go on with, e.g. --restart results/b1");
    if (run_output->count() + sweep_output->count() > 0 && output_dir.empty())
      throw rccm::InputError("-o: give the directory to write in, e.g. -o results/mine (an empty name would write to output.directory)");
    if (output_dir.rfind('-', 0) == 0)
      throw rccm::InputError("-o " + output_dir + ": a directory name that starts with '-' reads as an option (an option "
                             "after -o?); write ./" + output_dir + " if you mean that directory");
    if (!restart_dir.empty() && !output_dir.empty() && restart_dir != output_dir)
      throw rccm::InputError("--restart " + restart_dir + " and -o " + output_dir + ": a restart writes where it started");
    if (*sweep_app) {
      rccm::install_stop_handlers();
      return sweep(config_file, overrides, restart_dir.empty() ? output_dir : restart_dir, jobs, force,
                   !restart_dir.empty(), argv[0]);
    }
    // A restart writes where the run it continues wrote; -o is output.directory.
    if (!restart_dir.empty()) output_dir = restart_dir;
    if (!output_dir.empty()) overrides.push_back(rccm::string_override("output.directory", output_dir));
    if (*run) {  // from the config's reading on, a signal says where it stopped the run
      rccm::install_stop_handlers();
      rccm::exit_at_once_until_writing();
    }
    rccm::Config cfg = rccm::load_config(config_file, overrides);
    if (!output_dir.empty()) cfg.origins["output.directory"] = restart_dir.empty() ? "-o" : "--restart " + restart_dir;
    if (*run) {
      rccm::RunOptions options;
      options.step_log = verbose && root ? &std::cout : nullptr;
      options.progress = !quiet && root && isatty(fileno(stderr));
      options.write_files = root;
      options.force = force;
      options.restart = !restart_dir.empty();
      const rccm::RunResult r = rccm::Simulation(cfg, options).run();
      if (!root) return 0;
      print_totals(r);
      std::printf("# results in %s (report.txt, interface_t*.csv, history.csv, curves.csv, results.pvd)\n",
                  cfg.output.directory.c_str());
    } else {
      const std::vector<rccm::CompareCase> cases = rccm::run_comparison(cfg, integrators, solvers, euler_steps);
      std::cout << "# " << config_file << "\n";
      rccm::print_comparison(std::cout, cases);
      for (const rccm::CompareCase& c : cases)
        if (!c.failure.empty()) return 3;  // as a failed `rccm run`
    }
    return 0;
  } catch (const rccm::InputError& e) {
    if (root) say(std::string("rccm: error: ") + e.what());  // the same in every process
    return 2;
  } catch (const rccm::SolveError& e) {
    if (root) say(std::string("rccm: run failed: ") + e.what());
    return 3;
  } catch (const rccm::Interrupted& e) {
    if (root) say(std::string("rccm: ") + e.what() + "; the results up to that step are complete in the output directory");
    return 128 + e.signal;
  } catch (const std::exception& e) {
    say(std::string("rccm: internal error: ") + e.what());
    return 1;
  }
  }();
  // A process that stopped on an error stops the others, which could wait for it forever.
  if (status != 0 && rccm::parallel::size() > 1) rccm::parallel::abort(status);
  return status;
}
