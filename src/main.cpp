// rccm: quasi-static FE contact with the RCCM interface law, solved by the bipotential method.
// Exit status: 0 success, 2 bad input (nothing written), 3 a solve that failed, 1 anything else.
#include "rccm/config.hpp"
#include "rccm/errors.hpp"
#include "rccm/simulation.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"rccm: RCCM interface (contact, Coulomb friction, adhesion) by the bipotential method"};
  app.require_subcommand(1);
  std::string config_file;
  std::vector<std::string> overrides;
  bool quiet = false;

  CLI::App* run = app.add_subcommand("run", "run the problem of a config file");
  run->add_option("config", config_file, "libconfig file, e.g. config/b1.cfg")->required();
  run->add_option("--set", overrides, "override a setting: path=value (repeatable)");
  run->add_flag("--quiet,-q", quiet, "no per-step output");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  try {
    const rccm::Config cfg = rccm::load_config(config_file, overrides);
    rccm::Simulation sim(cfg, quiet ? nullptr : &std::cout);
    const rccm::RunTotals t = sim.run();
    std::printf("# %d steps, %ld contact solves, %.2f sweeps per solve (max %d), %.3f s\n", t.steps,
                t.contact_solves, double(t.sweeps) / std::max(1L, t.contact_solves), t.max_sweeps, t.wall_seconds);
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
