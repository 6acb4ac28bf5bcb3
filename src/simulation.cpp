#include "rccm/simulation.hpp"

#include "rccm/bipotential_solver.hpp"
#include "rccm/interface_state.hpp"
#include "rccm/model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace rccm {

std::vector<double> time_grid(const Config& cfg) {
  std::vector<double> t;
  for (int n = 1; n <= cfg.time.steps; ++n) t.push_back(cfg.time.T * n / cfg.time.steps);
  for (double o : cfg.output.times)
    if (o > 0) t.push_back(o);
  std::sort(t.begin(), t.end());
  const double eps = 1e-12 * cfg.time.T;
  t.erase(std::unique(t.begin(), t.end(), [eps](double a, double b) { return std::abs(a - b) <= eps; }), t.end());
  return t;
}

namespace {

void log_step(std::ostream& out, int step, const InterfaceState& st, const ContactSolution& s) {
  int count[3] = {0, 0, 0};
  for (Status x : st.status) ++count[static_cast<int>(x)];
  char line[160];
  std::snprintf(line, sizeof line, "%5d %10.5f %6d %7d %5d %10.2e %10.6f %5d %5d %5d\n", step, st.t,
                s.iterations, s.local_iterations, s.exact_solves, s.residual, st.beta.minCoeff(), count[1],
                count[2], count[0]);
  out << line;
}

}  // namespace

RunTotals Simulation::run() {
  const auto start = std::chrono::steady_clock::now();
  RunTotals totals;

  // 1. Set up: mesh, body (K0 factorized once), interface, condensation.
  const Model model(cfg_);
  const BipotentialSolver solver(cfg_.solver);
  InterfaceState state = InterfaceState::initial(model);
  if (log_)
    *log_ << "# " << cfg_.file << ": " << model.mesh().nodes.size() << " nodes, " << model.mesh().cells.size()
          << " cells, " << model.contact_nodes() << " contact nodes\n"
          << "# step      t [s] sweeps   local exact   residual   min beta stick slide   sep\n";

  // 2. Step the load with beta held at beta0 (the adhesion evolution is the integrator's job).
  int step = 0;
  for (double t : time_grid(cfg_)) {
    const ContactSolution s = solve_contact(model, solver, t, state.beta, state);
    state.commit(t, state.beta, s);
    ++step;
    ++totals.contact_solves;
    totals.sweeps += s.iterations;
    totals.max_sweeps = std::max(totals.max_sweeps, s.iterations);
    if (log_) log_step(*log_, step, state, s);
  }
  totals.steps = step;
  totals.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return totals;
}

}  // namespace rccm
