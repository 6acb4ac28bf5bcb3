// Description
//   How the viscosity alpha of the interface changes the peel of benchmark B1 (a thin
//   aluminium layer pulled off a rigid support at one end; docs/BENCHMARKS.md). For
//   each alpha one run gives the peak peel force at A, when it occurs, and the debonded length
//   (beta < 0.5) at t1 = 3.571 s and at T. More viscosity holds the layer longer: the peak
//   force and its time grow with alpha and less of the layer comes off. The program checks
//   that and exits with status 1 if it does not hold, so it runs as a test too.
//
// Sample runs
//   build/examples/peel_viscosity                          alpha = 0.1, 1, 10 on config/b1.cfg
//   build/examples/peel_viscosity config/b1.cfg 0.3 3 30   your config and alphas (N s/mm)
//
// A whole run is three library calls: load_config (with overrides, as `rccm run --set`),
// Simulation(cfg).run(), and the RunResult it returns. `rccm sweep` does the same for any
// setting, in parallel, with files.

#include "rccm/base/errors.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/io/config_reader.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  // 1. The command line: a config, then the alphas to compare (increasing).
  const std::string config = argc > 1 ? argv[1] : "config/b1.cfg";
  std::vector<std::string> alphas = {"0.1", "1", "10"};
  if (argc > 2) alphas.assign(argv + 2, argv + argc);

  std::printf("%10s %16s %12s %22s %18s %8s\n", "alpha", "peak force [N]", "at t [s]", "debonded at t1 [mm]",
              "debonded at T [mm]", "wall [s]");
  std::vector<rccm::RunResult> runs;
  try {
    for (const std::string& alpha : alphas) {
      // 2. The shipped config with one setting changed; no output times but t1 and T, no files.
      const rccm::Config cfg = rccm::load_config(config, {"interface.alpha=" + alpha, "output.times=[3.571]"});
      // 3. The run: model, contact solves, ARKODE, energy balance.
      runs.push_back(rccm::Simulation(cfg).run());
      const rccm::RunResult& r = runs.back();
      std::printf("%10s %16.4f %12.4f %22.3f %18.3f %8.3f\n", alpha.c_str(), std::abs(r.peak_force[0]), r.peak_time[0],
                  r.snapshots.front().debonded_length, r.snapshots.back().debonded_length, r.wall_seconds);
    }
  } catch (const rccm::InputError& e) {  // names the file, the line and the setting
    std::fprintf(stderr, "peel_viscosity: %s\n", e.what());
    return 2;
  } catch (const rccm::SolveError& e) {  // says where the run stopped and what to change
    std::fprintf(stderr, "peel_viscosity: %s\n", e.what());
    return 3;
  }

  // 4. The physics: a stronger interface for more viscosity.
  bool ok = true;
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const rccm::RunResult &weak = runs[k - 1], &strong = runs[k];
    if (std::abs(strong.peak_force[0]) <= std::abs(weak.peak_force[0]) || strong.peak_time[0] <= weak.peak_time[0] ||
        strong.snapshots.front().debonded_length > weak.snapshots.front().debonded_length) {
      std::fprintf(stderr, "peel_viscosity: alpha = %s does not hold the layer better than alpha = %s\n",
                   alphas[k].c_str(), alphas[k - 1].c_str());
      ok = false;
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
