// A restart point of a run (README "Interrupted runs and restart"): the committed interface
// state, the integrator's last step size and everything the result files and the report
// have accumulated, written atomically to output.directory/checkpoint.txt every
// output.checkpoint_steps accepted steps and when a run stops. `rccm run CONFIG --restart DIR`
// reads it and goes on. Numbers are stored as C99 hex floats: a restart reads back the very
// bits it wrote.
#pragma once

#include "rccm/time/beta_ode.hpp"
#include "rccm/base/config.hpp"
#include "rccm/time/energy_balance.hpp"
#include "rccm/model/interface_state.hpp"
#include "rccm/io/run_record.hpp"

#include <string>

namespace rccm {

struct Checkpoint {
  std::string settings;   // Config::settings of the run that wrote it
  std::string settings_parts;  // its Config::settings_parts (empty in a checkpoint of format 6)
  int step = 0;           // accepted steps so far
  double last_step = 0;   // s: the integrator's last accepted step size (ARKODE restarts with it)
  InterfaceState state;   // committed: t, beta, Rbar, u, y, status
  EnergyTerms energy;     // accumulated up to state.t
  std::vector<double> diagnostics;  // the integrator's (AdhesionIntegrator::diagnostics)
  BetaOde::Excursion excursion;     // of beta out of [0, previous beta] so far
  RunResult progress;     // snapshots, peak forces, solve and integrator counts (the step records
                          // are read back from history.csv)
  std::vector<int> contact_nodes;  // the mesh node of each pair, in the pairs' order (a restart
                                   // checks that its model lists them alike)
  Eigen::VectorXd springs_beta;    // the beta of K0's springs (Model::springs_beta): state.y is of them
  RunNotes notes;                  // what the run has said so far
};

/// The checkpoint's path in a result directory.
std::string checkpoint_path(const std::string& directory);

/// Writes DIR/checkpoint.txt atomically (AtomicFile); throws SolveError when it cannot.
void write_checkpoint(const std::string& directory, const Checkpoint& c);

/// Reads DIR/checkpoint.txt of a run of `cfg`; throws InputError naming the file and line
/// when it is missing, damaged (a value outside the state's range: beta outside [0, 1], t
/// outside [0, T], a NaN or an infinite energy, vectors of the wrong sizes), or was written by
/// a run of other settings.
Checkpoint read_checkpoint(const std::string& directory, const Config& cfg);

}  // namespace rccm
