// A whole run: set up the model, integrate beta to each output time, write and report.
#pragma once

#include "rccm/adhesion_integrator.hpp"
#include "rccm/config.hpp"
#include "rccm/energy_balance.hpp"

#include <Eigen/Core>

#include <iosfwd>
#include <string>
#include <vector>

namespace rccm {

/// The interface at an output time.
struct Snapshot {
  double t = 0;
  Eigen::VectorXd beta, Rbar, u;
  double debonded_length = 0;  // sum of the tributary lengths where beta < 0.5, mm
};

/// Work of one accepted step, for the report's per-step table (the paper's Tables 1-2).
struct StepRecord {
  int step = 0;
  double t = 0, dt = 0;
  long contact_solves = 0;
  double sweeps_mean = 0;
  int sweeps_max = 0;
  double cpu_seconds = 0;
};

struct RunResult {
  std::vector<Snapshot> snapshots;  // at the output times and at T
  std::vector<int> watched;         // contact node of each output.watch point
  std::vector<StepRecord> steps;    // every accepted step (step 0: the initial state)
  IntegratorStats integrator;
  SolveCounts solves;
  EnergyTerms energy;               // at T (MODEL.md s3)
  std::vector<double> peak_force;   // per load: largest |resultant force| over the run, N
  std::vector<double> peak_time;    // per load: when it occurred, s
  std::vector<std::string> warnings;
  std::string stopped;              // why the run ended before T (failure, signal); empty: complete
  int nodes = 0, cells = 0, contact_nodes = 0, dofs = 0;
  double setup_seconds = 0, wall_seconds = 0;
};

struct RunOptions {
  std::ostream* step_log = nullptr;  // one line per accepted step
  bool progress = false;             // one updating line on stderr
  bool write_files = false;          // results in output.directory
  bool force = false;                // overwrite the results of an earlier run there
  bool restart = false;              // go on from output.directory/checkpoint.txt (Checkpoint)
  BetaOde::Observer observer;        // called after each accepted step (tests)
};

class Simulation {
 public:
  Simulation(const Config& cfg, RunOptions options = {}) : cfg_(cfg), options_(std::move(options)) {}

  /// Runs the whole problem; throws InputError (bad model: nothing written), SolveError or
  /// Interrupted (the files then hold every accepted step, the last state, the report and a
  /// checkpoint to restart from).
  RunResult run();

 private:
  Config cfg_;
  RunOptions options_;
};

/// The accepted times of a fixed-step run: steps equal increments of [0, T] plus the output times.
std::vector<double> time_grid(const Config& cfg);

/// The times a run stops at: the output times in (0, T) and T.
std::vector<double> stop_times(const Config& cfg);

}  // namespace rccm
