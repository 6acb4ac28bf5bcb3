// A whole run: build the model, step the load, solve the interface, report.
#pragma once

#include "rccm/config.hpp"

#include <iosfwd>

namespace rccm {

struct RunTotals {
  int steps = 0;
  long contact_solves = 0;
  long sweeps = 0;
  int max_sweeps = 0;
  double wall_seconds = 0;
};

class Simulation {
 public:
  /// `log` receives one line per accepted step (nullptr: silent).
  Simulation(const Config& cfg, std::ostream* log) : cfg_(cfg), log_(log) {}

  /// Runs the whole problem; throws InputError (bad model) or SolveError (failed solve).
  RunTotals run();

 private:
  Config cfg_;
  std::ostream* log_;
};

/// The accepted times of a fixed-step run: steps equal increments of [0, T] plus the output times.
std::vector<double> time_grid(const Config& cfg);

}  // namespace rccm
