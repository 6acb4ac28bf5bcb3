// The CSV result files of a run, in output.directory (README "Result files"):
//   interface_t<time>.csv  interface fields at each output time
//   history.csv            solver work, watched points and probes at every accepted step
//   curves.csv             each load's value, resultant and displacement, the debonded
//                          length and the energy terms at every accepted step
// and the ParaView files (vtk_writer.hpp). The CSV streams grow by one complete line per
// accepted step; the other files are written whole under a temporary name and renamed.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/io/csv.hpp"
#include "rccm/io/run_record.hpp"
#include "rccm/io/vtk_writer.hpp"
#include "rccm/model/body_state.hpp"
#include "rccm/model/model.hpp"
#include "rccm/time/beta_ode.hpp"
#include "rccm/time/energy_balance.hpp"

#include <memory>
#include <string>
#include <vector>

namespace rccm {

/// Where a restarted run takes up its files: the checkpoint's time and output times.
struct ResumePoint {
  double t = 0;
  std::vector<double> output_times;  // of the snapshots taken up to t
  bool frame_at_t = false;           // the uninterrupted run has a ParaView frame at t (not only the stop's)
};

/// The debonded length: the measure of the interface where beta < 1/2 (the sum of the
/// tributary measures of those pairs), mm. One definition for every file and plot.
double debonded_length(const Model& model, const Eigen::VectorXd& beta);

/// history.csv's columns of the run's own figures, before those of the watch points and probes.
std::vector<std::string> history_run_columns();
/// history.csv's columns of a watch point (watch) or a probe named `name` in a mesh of `dim`.
std::vector<std::string> history_point_columns(const std::string& name, bool watch, int dim);

/// Load k's name in the result files' headers: "L1 top_left.y" (its number, node set and direction).
std::string load_label(const Config& cfg, std::size_t k);

class ResultWriter {
 public:
  /// Writes the CSV headers into `directory` (created and locked by the caller). With
  /// `resume`: keeps the lines and files of an earlier run up to resume->t and removes the
  /// rest (what an interrupted run wrote after its checkpoint), then appends.
  ResultWriter(const Model& model, const Config& cfg, const std::string& directory,
               const ResumePoint* resume = nullptr);

  void step(const AcceptedStep& a, const BodyState& b, const EnergyTerms& e);
  /// An output time: the interface file and a ParaView frame.
  void output(const InterfaceState& s, const BodyState& b);
  /// A ParaView frame only (t = 0, output.every).
  void frame(const InterfaceState& s, const BodyState& b) { vtk_.write(s, b); }
  const std::string& directory() const { return directory_; }
  /// The records of the steps an earlier run wrote into history.csv up to the resume point.
  const std::vector<StepRecord>& resumed_steps() const { return resumed_steps_; }

 private:
  const Model& model_;
  const Config& cfg_;
  std::string directory_;
  std::unique_ptr<CsvStream> history_, curves_;
  VtkWriter vtk_;
  std::vector<StepRecord> resumed_steps_;
};

}  // namespace rccm
