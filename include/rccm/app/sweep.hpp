// `rccm sweep`: one config run for every combination of listed setting values (an alpha
// study: --set interface.alpha=0,0.01,0.1,1,10,100), in parallel, each case in its own
// subdirectory, with a summary table and a plain job list for a cluster.
#pragma once

#include "rccm/app/simulation.hpp"
#include "rccm/base/config.hpp"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace rccm {

/// One swept setting: "interface.alpha" and its values as written ("0.01", "1", ...).
struct SweepAxis {
  std::string path;
  std::vector<std::string> values;
};

enum class CaseStatus { NotRun, Complete, Failed, Interrupted };
const char* case_status_name(CaseStatus s);

/// How a case starts: afresh, from the checkpoint of its stopped run (a resumed sweep), or
/// not at all: its directory holds its complete run, whose figures the summary reads.
enum class CaseStart { Fresh, Restart, Kept };

struct SweepCase {
  std::string name;                    // subdirectory, e.g. "alpha=0.01" or "alpha=1_mu=0.3"
  std::vector<std::string> values;     // its value of each axis
  std::vector<std::string> overrides;  // path=value of this case (the fixed ones first)
  Config config;
  RunResult result;
  std::optional<Mesh> mesh;           // read before the cases run (run_sweep)
  CaseStart start = CaseStart::Fresh;
  CaseStatus status = CaseStatus::NotRun;
  std::string error;                   // a case that failed or was interrupted: its message
  int signal = 0;                      // the signal that interrupted it
};

/// Splits --set items into sweep axes (a value with commas outside brackets) and plain
/// overrides (everything else).
void split_sweep_settings(const std::vector<std::string>& items, std::vector<SweepAxis>& axes,
                          std::vector<std::string>& fixed);

/// Builds the cases (the grid of all axes). Throws InputError for a bad case config, before
/// any case runs.
std::vector<SweepCase> make_sweep_cases(const std::string& config_file, const std::vector<std::string>& fixed,
                                        const std::vector<SweepAxis>& axes, const std::string& directory);

/// `rccm sweep --restart DIR`: decides each case's start from its directory, before anything
/// runs: a complete run of the case's settings is kept (its report read), a stopped one goes
/// on from its checkpoint, a case without a checkpoint runs afresh. Throws InputError
/// (nothing written) when a directory holds a run of other settings or a damaged checkpoint.
/// Returns one line per case that is not run afresh from an empty directory, for the user.
std::vector<std::string> plan_resumed_sweep(std::vector<SweepCase>& cases);

/// Runs the cases on `jobs` threads, each writing into its directory (`force`: over earlier
/// results), as their `start` says (a kept case is not run). The gmsh files are read first,
/// one case after the other on the calling thread, a geometry the cases share once
/// (GmshReuse), and each case is handed its mesh: a case whose mesh is refused is failed
/// before any case computes. A stop request (SIGINT, SIGTERM) stops the running cases at their next accepted
/// step and starts no other: the cases not run keep the status NotRun.
void run_sweep(std::vector<SweepCase>& cases, int jobs, bool force = false);

/// The tools/plot command that overlays this sweep's cases with results into `directory` (the
/// cases named one by one: the directory may also hold an earlier sweep's); "" if none has any.
std::string overlay_command(const std::string& directory, const std::vector<SweepCase>& cases);

/// The command that goes on with an interrupted sweep: `rccm sweep CONFIG --set ... -j N --restart DIR`.
std::string resume_command(const std::string& rccm_path, const std::string& config_file,
                           const std::vector<std::string>& overrides, int jobs, const std::string& directory);

/// summary.csv (one row per case: its value of each axis, its status, its figures, empty
/// cells where a case did not complete) in `directory`, and the table on `out`.
void write_sweep_summary(std::ostream& out, const std::string& directory, const std::vector<SweepAxis>& axes,
                         const std::vector<SweepCase>& cases);

/// jobs.txt in `directory`: one `rccm run` line per case (the same study on a cluster).
/// Written before the cases run: a sweep killed halfway leaves it, and its directory is
/// known as a sweep's.
void write_sweep_jobs(const std::string& directory, const std::vector<SweepCase>& cases, const std::string& rccm_path,
                      const std::string& config_file);

}  // namespace rccm
