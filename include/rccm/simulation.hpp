// A whole run: set up the model, integrate beta to each output time, report.
#pragma once

#include "rccm/adhesion_integrator.hpp"
#include "rccm/config.hpp"

#include <Eigen/Core>

#include <iosfwd>
#include <string>
#include <vector>

namespace rccm {

/// The interface at an output time.
struct Snapshot {
  double t = 0;
  Eigen::VectorXd beta, Rbar, u;
};

struct RunResult {
  std::vector<Snapshot> snapshots;  // at the output times and at T
  std::vector<int> watched;         // contact node of each output.watch point
  IntegratorStats integrator;
  SolveCounts solves;
  std::vector<std::string> warnings;
  double setup_seconds = 0, wall_seconds = 0;
};

class Simulation {
 public:
  /// `log` receives one line per accepted step (nullptr: silent); `observer`, if set, is
  /// called after each accepted step too (tests, writers).
  Simulation(const Config& cfg, std::ostream* log, BetaOde::Observer observer = {})
      : cfg_(cfg), log_(log), observer_(std::move(observer)) {}

  /// Runs the whole problem; throws InputError (bad model) or SolveError (failed solve).
  RunResult run();

 private:
  Config cfg_;
  std::ostream* log_;
  BetaOde::Observer observer_;
};

/// The accepted times of a fixed-step run: steps equal increments of [0, T] plus the output times.
std::vector<double> time_grid(const Config& cfg);

/// The times a run stops at: the output times in (0, T) and T.
std::vector<double> stop_times(const Config& cfg);

}  // namespace rccm
