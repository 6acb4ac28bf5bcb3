// The run report: the paper's Table 1 layout (work per step at steps 1, 10, 40, 60, 100,
// 150, 200 or the nearest ones; its CPU times are wall times here), integrator totals, energy
// balance and wall time; as text
// (report.txt) and JSON (report.json) for scripts.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/io/run_record.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace rccm {

/// A column of the paper's Table 1 layout: the step the paper would number it, and the
/// accepted step recorded there.
struct PaperColumn {
  int step;
  const StepRecord* record;
};
/// The accepted steps of the paper's table columns (steps 1, 10, 40, 60, 100, 150, 200). On a
/// fixed grid of time.steps steps (every method but ARKODE) step k is the one that ends at
/// k T / steps, whatever output times off the grid added between (B1's t1 = 3.571 s, a
/// rounded 75 T / 210); with ARKODE the k-th accepted step. At most `last` (and the run's
/// last step): the last column of several runs compared side by side is one they all reached.
std::vector<PaperColumn> paper_table_columns(const Config& cfg, const RunResult& r, int last = 1 << 30);

void write_report_text(std::ostream& out, const Config& cfg, const RunResult& r);

/// How many of the compressed W0's sweeps several threads shared ("sweeps in 2 threads: 4794 of
/// the compressed W0's 5004 ..."; la/thread_choice.hpp), for report.txt and the closing lines;
/// empty where none was timed or they had one thread to take.
std::string threaded_sweeps_line(const SolveCounts& solves, int most_threads);

void write_report_json(std::ostream& out, const Config& cfg, const RunResult& r);

/// A complete run as its report.json tells it (a resumed sweep's kept case).
struct ReportedRun {
  RunResult result;           // totals, energy, peak forces, debonded length at its snapshots,
                              // warnings: no fields, no per-step work
  bool same_controls = true;  // run with cfg's numerical controls (Config::controls_fingerprint)
};

/// What report.json in `directory` says of a complete run of `cfg`; throws InputError naming
/// the file when it cannot be read, holds a run of other settings or one that did not complete.
ReportedRun read_report_json(const std::string& directory, const Config& cfg);

/// Writes report.txt and report.json into `directory`.
void write_reports(const std::string& directory, const Config& cfg, const RunResult& r);

}  // namespace rccm
