// Where a run writes its results (output.directory): checked before the model is built,
// without creating anything, then claimed for the run's life.
#pragma once

#include "rccm/base/config.hpp"

#include <optional>
#include <string>

namespace rccm {

/// Whether `directory` holds the results of a run, complete or not (history.csv, report.txt
/// or results.pvd).
bool holds_results(const std::string& directory);

/// Whether `directory` holds a run that reached T (its report.txt says `status: complete`).
bool holds_complete_run(const std::string& directory);

/// Throws InputError "file:line: output.directory: ..." when the directory cannot be created
/// or written, or already holds the results of a run and `force` is false. Creates nothing.
void check_output_directory(const Config& cfg, bool force);

/// Throws InputError "file:line: output.directory: ..." when an entry of the (existing) output
/// directory bears the name of a file rccm writes there but is no file (a folder the run would
/// fail to write over, after computing up to it): before a fresh run and a restart.
void check_result_names(const Config& cfg);

/// Whether `name` is the interface file of an output time as a run names it: "interface_t",
/// the time as csv_number writes it, ".csv" (interface_t3.571.csv, interface_t1e-05.csv); not
/// a user's interface_thickness.csv or interface_t0.36.csv.bak.
bool interface_time_file(const std::string& name);

/// Refuses (InputError, `option` named) a file that could not be written at `path`: its
/// directory missing or not writable, or a directory in its place. Checked before the work
/// whose result it would keep.
void check_output_file(const std::string& path, const std::string& option);

/// Holds an exclusive lock on DIR/.lock while alive (DIR exists); throws InputError
/// "<where>: another rccm run is writing into 'DIR' now; ..." when another process holds it.
class DirectoryLock {
 public:
  DirectoryLock(const std::string& directory, const std::string& where);
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

/// Creates output.directory and holds an exclusive lock on DIR/.lock while alive: a second
/// run into the same directory is refused while this one runs (even with --force). `fresh`:
/// the result files of an earlier run there (and its plots/) are removed first, so that a
/// forced run starts from an empty result set; other files are left alone.
class OutputDirectory {
 public:
  OutputDirectory(const Config& cfg, bool fresh);
  ~OutputDirectory();
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::optional<DirectoryLock> lock_;
};

}  // namespace rccm
