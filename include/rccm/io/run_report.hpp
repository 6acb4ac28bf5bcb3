// The run report: the paper's Table 1 layout (work per step at steps 1, 10, 40, 60, 100,
// 150, 200 or the nearest ones), integrator totals, energy balance and wall time; as text
// (report.txt) and JSON (report.json) for scripts.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/io/run_record.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace rccm {

/// The accepted steps nearest to the paper's table columns (steps 1, 10, 40, 60, 100, 150, 200).
std::vector<const StepRecord*> paper_table_columns(const RunResult& r);

void write_report_text(std::ostream& out, const Config& cfg, const RunResult& r);
void write_report_json(std::ostream& out, const Config& cfg, const RunResult& r);

/// What report.json in `directory` says of a run of `cfg` (its totals, energy, peak forces,
/// the debonded length at its snapshots, warnings: no fields, no per-step work); throws
/// InputError naming the file when it cannot be read or holds a run of other settings.
RunResult read_report_json(const std::string& directory, const Config& cfg);

/// Writes report.txt and report.json into `directory`.
void write_reports(const std::string& directory, const Config& cfg, const RunResult& r);

}  // namespace rccm
