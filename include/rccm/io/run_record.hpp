// What a run leaves behind in memory: snapshots of the interface at the output times, the
// work of every accepted step, totals, the energy balance and peak forces.
#pragma once

#include "rccm/time/beta_ode.hpp"
#include "rccm/time/energy_balance.hpp"
#include "rccm/time/integrator.hpp"

#include <Eigen/Core>

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
  double wall_seconds = 0;
};

/// What a run has said while it ran (Recorder: a crawl, a body leaving small strains), kept
/// by its checkpoints so that a restart's report still holds it and does not say it again.
struct RunNotes {
  std::vector<std::string> said;      // each once, in order; the report's warnings repeat them
  bool deformation_noted = false;     // the small-strain note is among them
  double deformation_checked = -1e300;  // the last time small strains were due to be checked, s
};

struct RunResult {
  std::vector<Snapshot> snapshots;  // at the output times and at T
  std::vector<int> watched;         // contact pair of each output.watch point
  std::vector<StepRecord> steps;    // every accepted step (step 0: the initial state)
  IntegratorStats integrator;
  SolveCounts solves;
  EnergyTerms energy;               // at T (docs/MODEL.md s3)
  std::vector<double> peak_force;   // per load: largest |resultant force| over the run, N
  std::vector<double> peak_time;    // per load: when it occurred, s
  std::vector<std::string> warnings;
  std::string stopped;              // why the run ended before T (failure, signal); empty: complete
  int nodes = 0, cells = 0, contact_nodes = 0, dofs = 0;
  std::string linear_solver;             // who solved the body's K0: "CHOLMOD", "PETSc MUMPS on 2 processes"
  std::string flexibility;               // how W0 was stored at the setup (DelassusOperator::storage)
  std::vector<std::string> bodies;       // the mesh's bodies
  std::vector<int> pairs_per_interface;  // contact pairs of each config interface
  double setup_seconds = 0, wall_seconds = 0;  // of this process: a restart's since it restarted
  long body_solves = 0;                         // full displacements solved (frames, output times, strain checks)
  double body_solve_seconds = 0;                // their wall time: the body's solve phase, one right-hand side
  long strain_checks = 0;                       // small-strain checks made (Recorder::note_deformation)
  long strain_checks_left_out = 0;              // and left out: their solves would pass RunOptions::strain_check_share
  double restarted_at = -1;                     // the checkpoint's time a restart went on from; -1: none
  SolveCounts solves_before_restart;            // the checkpoint's: `solves` less these is this process's
};

/// The contact solves this process made (a restart's since it restarted, as wall_seconds):
/// their count and time, for the times per solve beside the wall time.
inline SolveCounts solves_of_this_process(const RunResult& r) {
  SolveCounts s = r.solves;
  s.contact_solves -= r.solves_before_restart.contact_solves;
  s.seconds -= r.solves_before_restart.seconds;
  return s;
}

}  // namespace rccm
