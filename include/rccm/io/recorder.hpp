// Everything a run records besides the physics (README "Result files"): the result files,
// checkpoints and a restart from one, the energy balance and peak forces, the per-step
// records, the step log and the progress line, and the report at the end. Simulation::run()
// hands it each stage's outcome; it owns no physics.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/elasticity.hpp"
#include "rccm/io/checkpoint.hpp"
#include "rccm/io/output_directory.hpp"
#include "rccm/io/result_writer.hpp"
#include "rccm/io/run_record.hpp"
#include "rccm/model/body_state.hpp"
#include "rccm/model/model.hpp"
#include "rccm/time/beta_ode.hpp"
#include "rccm/time/energy_balance.hpp"
#include "rccm/time/integrator.hpp"

#include <chrono>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace rccm {

struct RunOptions {
  std::ostream* step_log = nullptr;  // one line per accepted step
  bool progress = false;             // one updating line on stderr
  bool write_files = false;          // results in output.directory
  bool force = false;                // overwrite the results of an earlier run there
  bool restart = false;              // go on from output.directory/checkpoint.txt (Checkpoint)
  BetaOde::Observer observer;        // called after each accepted step (tests)
  std::string label;                 // said before its notes on stderr (a sweep's case: "alpha=0.1")
  /// The small-strain checks' solves of the body take at most this share of the run's time
  /// after its setup (the checks where the body is solved anyway excepted: frames, output
  /// times, T).
  double strain_check_share = 0.1;
};

class Recorder {
 public:
  /// Checks the output directory, or reads the checkpoint to restart from, before anything
  /// is built or written (throws InputError).
  Recorder(const Config& cfg, RunOptions options);

  /// The model is built: its size for the report, and the result files (a restart takes up
  /// the files of the run it continues, up to its checkpoint).
  void open(const Model& model);

  /// The state the run starts from, committed on `ode`: t = 0 (accepted, so recorded as
  /// step 0), or the checkpoint's.
  void start(BetaOde& ode);

  /// Records an accepted step: energy, peak forces, step record, files, logs, checkpoints.
  void step(const AcceptedStep& a);

  /// The integrator's first step (a restart begins with the step it stopped at; 0: its own).
  double initial_step() const;
  /// The integrator is made: a restart restores what it had observed.
  void attach(BetaIntegrator& integrator);

  /// Whether the snapshot at t_out has been taken (before a restart's checkpoint).
  bool has_snapshot(double t_out) const;
  /// The interface and the mesh at the committed state: an output time.
  void snapshot();

  /// The end of a complete run: a checkpoint of the last state, totals and the report.
  RunResult finish();
  /// The end of a run stopped before T (`why`): as finish(), with a snapshot of the last
  /// accepted state. Never throws: returns what a message should add (where the results
  /// are, or that the files could not be written).
  std::string stop(const std::string& why);

 private:
  bool rate_independent() const { return cfg_.integrator.method == Method::RateIndependent; }
  RunResult close(const std::string& stopped);
  /// The last accepted step's bulk with its full fields (one solve of the body, at most once a
  /// step): for frames, output times and the strain check; the other steps need its resultants only.
  const BodyState& fields();
  void note_crawl(const AcceptedStep& a);
  void note_deformation(const AcceptedStep& a);
  void note(const std::string& text);
  /// "rccm: [label: ]note: text" on stderr, after `lead` (a line break ending the progress line).
  void say_note(const std::string& text, const char* lead = "") const;
  void save_checkpoint();
  double seconds() const;

  const Config& cfg_;
  RunOptions options_;
  const std::vector<double> stops_;  // the output times and T (stop_times): the body is solved there
  std::chrono::steady_clock::time_point start_;
  std::unique_ptr<Checkpoint> resume_;
  const Model* model_ = nullptr;
  BetaOde* ode_ = nullptr;
  BetaIntegrator* integrator_ = nullptr;
  std::unique_ptr<OutputDirectory> directory_;
  std::unique_ptr<ResultWriter> writer_;
  std::unique_ptr<EnergyBalance> energy_;
  BodyState body_;            // of the last accepted step: its resultants, and its fields once fields() asked
  IntegratorStats earlier_;   // counts of the run a restart continues
  RunResult result_;
  int tiny_steps_ = 0;                    // accepted steps in a row below 1e-7 T
  RunNotes notes_;                        // said while the run runs (and before a restart)
  std::unique_ptr<SmallStrainCheck> small_strains_;
  int rows_step_ = -1;                    // the last accepted step whose CSV rows are written
};

}  // namespace rccm
