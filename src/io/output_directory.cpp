#include "rccm/io/output_directory.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/io/csv.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

namespace fs = std::filesystem;

namespace rccm {

namespace {
// The files that mark a directory as holding a run's results.
const char* const result_marks[] = {"history.csv", "report.txt", "results.pvd"};

/// What lies between `head` and `tail` in `name`, if it begins with the one and ends with the other.
std::optional<std::string> between(const std::string& name, const std::string& head, const std::string& tail) {
  if (name.size() < head.size() + tail.size() || name.compare(0, head.size(), head) != 0 ||
      name.compare(name.size() - tail.size(), tail.size(), tail) != 0)
    return std::nullopt;
  return name.substr(head.size(), name.size() - head.size() - tail.size());
}

/// Whether `name` is head, a frame number (four digits or more, as VtkWriter numbers its
/// frames), tail: mesh_0003.vtu, not mesh_coarse.vtu.
bool frame_file(const std::string& name, const std::string& head, const std::string& tail) {
  const std::optional<std::string> number = between(name, head, tail);
  return number && number->size() >= 4 &&
         std::all_of(number->begin(), number->end(), [](unsigned char c) { return std::isdigit(c); });
}

/// Whether a file name is one rccm writes into an output directory, exactly: its fixed files,
/// the frames, the interface files of output times, and AtomicFile's temporary of each (NAME.tmp).
bool result_file(std::string name) {
  if (const std::optional<std::string> base = between(name, "", ".tmp"); base && !base->empty()) name = *base;
  for (const char* f : {"history.csv", "curves.csv", "report.txt", "report.json", "results.pvd", "interface.pvd",
                        "checkpoint.txt"})
    if (name == f) return true;
  return interface_time_file(name) || frame_file(name, "mesh_", ".vtu") || frame_file(name, "interface_", ".vtp");
}

/// Removes the plots tools/plot wrote into `plots` (the names in its manifest), and the
/// directory if nothing else is left in it: the user's own files there stay.
void remove_plots(const fs::path& plots) {
  std::error_code ec;
  std::ifstream manifest(plots / ".rccm-plots");
  for (std::string name; read_line(manifest, name);)
    if (!name.empty() && name.find('/') == std::string::npos && name != "." && name != "..") fs::remove(plots / name, ec);
  manifest.close();
  fs::remove(plots / ".rccm-plots", ec);
  fs::remove(plots / ".rccm-plots.tmp", ec);
  if (fs::is_empty(plots, ec)) fs::remove(plots, ec);
}

/// Whether `dir` holds a run that stopped before T with a checkpoint (its report not complete).
bool stopped(const fs::path& dir) {
  std::error_code ec;
  return !holds_complete_run(dir.string()) && fs::exists(dir / "checkpoint.txt", ec);
}

/// Whether a file can be created in `dir` (a probe created and removed at once: permissions,
/// a read-only file system and /proc all answer, also for root).
bool writable(const fs::path& dir) {
  std::string probe = (dir / ".rccm-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) return false;
  ::close(fd);
  ::unlink(probe.c_str());
  return true;
}
}  // namespace

bool interface_time_file(const std::string& name) {
  const std::optional<std::string> time = between(name, "interface_t", ".csv");
  if (!time || time->empty()) return false;
  const double t = std::strtod(time->c_str(), nullptr);
  return std::isfinite(t) && csv_number(t) == *time;  // the whole of it a number, written as the run writes it
}

bool holds_results(const std::string& directory) {
  std::error_code ec;
  for (const char* mark : result_marks)
    if (fs::exists(fs::path(directory) / mark, ec)) return true;
  return false;
}

bool holds_complete_run(const std::string& directory) {
  std::ifstream report(fs::path(directory) / "report.txt");
  for (std::string line; read_line(report, line);)
    if (line.rfind("status: complete", 0) == 0) return true;
  return false;
}

void check_output_directory(const Config& cfg, bool force) {
  const fs::path dir = cfg.output.directory;
  const std::string where = cfg.where("output.directory");
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw InputError(where + ": '" + dir.string() + "' is a file, not a directory");
    if (!writable(dir)) throw InputError(where + ": cannot write into '" + dir.string() + "'");
    check_result_names(cfg);
    for (const char* mark : result_marks)
      if (!force && fs::exists(dir / mark, ec))
        throw InputError(where + ": '" + dir.string() + "' already holds the results of a run (" + mark + "); give " +
                         (stopped(dir) ? "--restart " + dir.string() + " to go on with it, " : "") +
                         "--force to overwrite them, or another directory (-o DIR)");
    return;
  }
  // It will be created: its nearest existing ancestor must be a writable directory.
  fs::path parent = fs::absolute(dir, ec).parent_path();
  while (!parent.empty() && !fs::exists(parent, ec) && parent != parent.root_path()) parent = parent.parent_path();
  if (!fs::is_directory(parent, ec) || !writable(parent))
    throw InputError(where + ": cannot create '" + dir.string() + "' ('" + parent.string() + "' is not a writable directory)");
}

void check_result_names(const Config& cfg) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(cfg.output.directory, ec))
    if (result_file(entry.path().filename().string()) && !entry.is_regular_file(ec))
      throw InputError(cfg.where("output.directory") + ": '" + entry.path().string() + "' is not a file but has the "
                       "name of one rccm writes there; rename or move it");
}

OutputDirectory::OutputDirectory(const Config& cfg, bool fresh) : path_(cfg.output.directory) {
  const std::string where = cfg.where("output.directory");
  std::error_code ec;
  fs::create_directories(path_, ec);
  if (ec || !fs::is_directory(path_))
    throw InputError(where + ": cannot create '" + path_ + "' (" + ec.message() + ")");
  lock_.emplace(path_, where);
  if (!fresh) return;
  for (const auto& entry : fs::directory_iterator(path_, ec))  // files only (a folder named alike was refused before)
    if (result_file(entry.path().filename().string()) && entry.is_regular_file(ec)) fs::remove(entry.path(), ec);
  if (fs::is_directory(fs::path(path_) / "plots", ec)) remove_plots(fs::path(path_) / "plots");
}

OutputDirectory::~OutputDirectory() = default;

DirectoryLock::DirectoryLock(const std::string& directory, const std::string& where) {
  const std::string lock = directory + "/.lock";
  fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(where + ": cannot write into '" + directory + "'");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    throw InputError(where + ": another rccm run is writing into '" + directory + "' now; wait for it, or choose another directory");
  }
}

DirectoryLock::~DirectoryLock() {
  ::close(fd_);  // releases the lock; the empty .lock file stays (removing it would race)
}

void check_output_file(const std::string& path, const std::string& option) {
  std::error_code ec;
  const fs::path file(path), dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  if (fs::is_directory(file, ec)) throw InputError(option + " " + path + ": a directory, not a file");
  if (!fs::is_directory(dir, ec) || !writable(dir))
    throw InputError(option + " " + path + ": cannot write into '" + dir.string() + "' (not a writable directory)");
}

}  // namespace rccm
