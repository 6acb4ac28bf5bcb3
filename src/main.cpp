// rccm: quasi-static FE contact with the RCCM interface law, solved by the bipotential method.
// Exit status: 0 success, 2 bad input (nothing written), 3 a solve that failed, 1 anything else.
#include "rccm/compare.hpp"
#include "rccm/config.hpp"
#include "rccm/errors.hpp"
#include "rccm/simulation.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <unistd.h>
#include <iostream>

namespace {

void print_totals(const rccm::RunResult& r) {
  const double per_solve = (r.wall_seconds - r.setup_seconds) / std::max(1L, r.solves.contact_solves);
  std::printf("# %ld steps (%ld rejected), %ld contact solves, %.2f sweeps per solve (max %d)\n"
              "# wall %.3f s: setup %.4f s, %.1f us per contact solve\n",
              r.integrator.steps, r.integrator.rejected, r.solves.contact_solves,
              double(r.solves.sweeps) / std::max(1L, r.solves.contact_solves), r.solves.max_sweeps, r.wall_seconds,
              r.setup_seconds, 1e6 * per_solve);
  for (const std::string& w : r.warnings) std::cerr << "rccm: warning: " << w << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rccm: RCCM interface (contact, Coulomb friction, adhesion) by the bipotential method"};
  app.require_subcommand(1);
  std::string config_file;
  std::vector<std::string> overrides, integrators{"arkode", "euler"};
  bool quiet = false;
  int euler_steps = 0;

  CLI::App* run = app.add_subcommand("run", "run the problem of a config file");
  CLI::App* compare = app.add_subcommand("compare", "run one problem with several integrators, side by side");
  for (CLI::App* sub : {run, compare}) {
    sub->add_option("config", config_file, "libconfig file, e.g. config/b1.cfg")->required();
    sub->add_option("--set", overrides, "override a setting: path=value (repeatable)");
  }
  bool verbose = false;
  run->add_flag("--quiet,-q", quiet, "no progress line");
  run->add_flag("--verbose,-v", verbose, "one line per accepted step on stdout");
  compare->add_option("--integrators", integrators, "comma-separated: arkode, euler, rate-independent, fixed")
      ->delimiter(',');
  compare->add_option("--euler-steps", euler_steps, "fixed steps of the euler case (default: time.steps)")
      ->check(CLI::PositiveNumber);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  try {
    const rccm::Config cfg = rccm::load_config(config_file, overrides);
    if (*run) {
      rccm::RunOptions options;
      options.step_log = verbose ? &std::cout : nullptr;
      options.progress = !quiet && isatty(fileno(stderr));
      options.write_files = true;
      const rccm::RunResult r = rccm::Simulation(cfg, options).run();
      print_totals(r);
      std::printf("# results in %s (report.txt, interface_t*.csv, history.csv, curves.csv, results.pvd)\n",
                  cfg.output.directory.c_str());
    } else {
      std::cout << "# " << config_file << "\n";
      rccm::print_comparison(std::cout, rccm::run_comparison(cfg, integrators, euler_steps));
    }
    return 0;
  } catch (const rccm::InputError& e) {
    std::cerr << "rccm: error: " << e.what() << "\n";
    return 2;
  } catch (const rccm::SolveError& e) {
    std::cerr << "rccm: run failed: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "rccm: internal error: " << e.what() << "\n";
    return 1;
  }
}
