#include "rccm/app/sweep.hpp"

#include "rccm/app/stop_request.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/fem/gmsh_mesh.hpp"
#include "rccm/fem/mesh_source.hpp"
#include "rccm/io/atomic_file.hpp"
#include "rccm/io/checkpoint.hpp"
#include "rccm/io/config_reader.hpp"
#include "rccm/io/csv.hpp"
#include "rccm/io/output_directory.hpp"
#include "rccm/io/result_writer.hpp"
#include "rccm/io/run_report.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdlib>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <optional>
#include <ostream>
#include <thread>
#include <utility>

namespace rccm {

namespace {

/// Splits at commas that are not inside [ ] or ( ) or quotes.
std::vector<std::string> split_top_level(const std::string& s) {
  std::vector<std::string> parts(1);
  int depth = 0;
  bool quoted = false;
  for (char c : s) {
    if (c == '"') quoted = !quoted;
    if (!quoted && (c == '[' || c == '(')) ++depth;
    if (!quoted && (c == ']' || c == ')')) --depth;
    if (c == ',' && depth == 0 && !quoted)
      parts.emplace_back();
    else
      parts.back() += c;
  }
  return parts;
}

std::string leaf(const std::string& path) { return path.substr(path.rfind('.') + 1); }

/// A message on one line (a CSV row per case), its line breaks and indents as single spaces.
std::string one_line(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool space = c == '\n' || c == ' ';
    if (!space) out += c;
    else if (!out.empty() && out.back() != ' ') out += ' ';
  }
  return out;
}

/// A word for a POSIX shell, in single quotes.
std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Two values of a sweep's list that set the same: the same text, or the same number however
/// written (0.1, 0.10, 1e-1).
bool same_value(const std::string& a, const std::string& b) {
  if (a == b) return true;
  // A whole number (spaces around it allowed, as in "0.1, 0.10"), or nothing.
  const auto number = [](const std::string& text) -> std::optional<double> {
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    while (end != text.c_str() && std::isspace(static_cast<unsigned char>(*end))) ++end;
    if (end == text.c_str() || *end != '\0') return std::nullopt;
    return x;
  };
  const std::optional<double> x = number(a), y = number(b);
  return x && y && *x == *y;
}

}  // namespace

const char* case_status_name(CaseStatus s) {
  switch (s) {
    case CaseStatus::NotRun: return "not run";
    case CaseStatus::Complete: return "complete";
    case CaseStatus::Failed: return "failed";
    case CaseStatus::Interrupted: return "interrupted";
  }
  return "";
}

void split_sweep_settings(const std::vector<std::string>& items, std::vector<SweepAxis>& axes,
                          std::vector<std::string>& fixed) {
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    const std::vector<std::string> values = eq == std::string::npos ? std::vector<std::string>{}
                                                                    : split_top_level(item.substr(eq + 1));
    if (values.size() > 1)
      axes.push_back({item.substr(0, eq), values});
    else
      fixed.push_back(item);
  }
  // A setting given twice would be one case's value and another's silently, a value listed
  // twice two cases into one directory.
  std::vector<std::string> paths;
  for (const std::string& item : fixed) paths.push_back(item.substr(0, item.find('=')));
  for (const SweepAxis& a : axes) {
    if (a.path == "output.directory")  // each case's is DIR/<case>: the list would be ignored, its cases alike
      throw InputError("sweep: --set output.directory cannot be swept: the sweep decides each case's directory "
                       "(DIR/<case>, named by the case's swept values); -o DIR chooses the sweep's directory, their parent");
    if (std::find(paths.begin(), paths.end(), a.path) != paths.end())
      throw InputError("sweep: --set " + a.path + " is given more than once: give each setting once (a list sweeps it)");
    paths.push_back(a.path);
    for (std::size_t k = 0; k < a.values.size(); ++k)
      for (std::size_t j = 0; j < k; ++j)
        if (same_value(a.values[j], a.values[k]))
          throw InputError("sweep: --set " + a.path + " lists " +
                           (a.values[j] == a.values[k] ? a.values[k] + " twice"
                                                       : a.values[j] + " and " + a.values[k] + ", the same number") +
                           ": give each value once");
  }
}

std::vector<SweepCase> make_sweep_cases(const std::string& config_file, const std::vector<std::string>& fixed,
                                        const std::vector<SweepAxis>& axes, const std::string& directory) {
  std::vector<SweepCase> cases(1);
  for (const SweepAxis& axis : axes) {
    std::vector<SweepCase> grown;
    for (const SweepCase& c : cases)
      for (const std::string& v : axis.values) {
        SweepCase n = c;
        std::string part = v;  // a value with a path in it names one directory, not a nest
        std::replace(part.begin(), part.end(), '/', '_');
        n.name += (n.name.empty() ? "" : "_") + leaf(axis.path) + "=" + part;
        n.values.push_back(v);
        n.overrides.push_back(axis.path + "=" + v);
        grown.push_back(n);
      }
    cases = grown;
  }
  for (std::size_t k = 0; k < cases.size(); ++k)
    for (std::size_t j = 0; j < k; ++j)
      if (cases[j].name == cases[k].name)
        throw InputError("sweep: two cases would share the directory " + cases[k].name +
                         " (a '/' in a value becomes '_' there): give values that differ otherwise");
  // A case's directory is one name of the file system: longer than NAME_MAX (255 bytes), the
  // case could not run and its directory could not be looked at. Its longest value is named.
  for (const SweepCase& c : cases)
    if (c.name.size() > NAME_MAX) {
      std::size_t k = 0;
      for (std::size_t j = 1; j < c.values.size(); ++j)
        if (c.values[j].size() > c.values[k].size()) k = j;
      const std::string& v = c.values[k];
      throw InputError("sweep: --set " + axes[k].path + "=" +
                       (v.size() > 40 ? v.substr(0, 32) + "... (" + std::to_string(v.size()) + " characters)" : v) +
                       ": its case's directory name would be " + std::to_string(c.name.size()) + " bytes, more than the " +
                       std::to_string(NAME_MAX) + " a file system allows in a name: give a shorter value");
    }
  const GmshReuse reuse;  // the cases' geometry read once when no case changes it
  for (SweepCase& c : cases) {
    c.overrides.insert(c.overrides.begin(), fixed.begin(), fixed.end());
    std::vector<std::string> all = c.overrides;
    all.push_back(string_override("output.directory", directory + "/" + c.name));
    c.config = load_config(config_file, all);
    c.config.origins["output.directory"] = "the sweep's directory " + directory;
  }
  return cases;
}

std::vector<std::string> plan_resumed_sweep(std::vector<SweepCase>& cases) {
  std::vector<std::string> notes;
  for (SweepCase& c : cases) {
    const std::string& dir = c.config.output.directory;
    try {
      check_output_directory(c.config, true);  // a directory it can write (results there are for below)
      if (holds_complete_run(dir)) {
        const ReportedRun kept = read_report_json(dir, c.config);
        c.result = kept.result;
        c.start = CaseStart::Kept;
        c.status = CaseStatus::Complete;
        notes.push_back(c.name + ": complete, kept" +
                        (kept.same_controls ? std::string()
                                       : " (it ran with other numerical controls than this sweep's: solver or "
                                         "integrator tolerances, iterations, steps; its report.txt has its own)"));
      } else if (std::filesystem::exists(checkpoint_path(dir))) {
        const Checkpoint checkpoint = read_checkpoint(dir, c.config);  // refused here if not this case's
        c.start = CaseStart::Restart;
        notes.push_back(c.name + ": goes on from its checkpoint at t = " + csv_number(checkpoint.state.t) + " s");
      } else if (holds_results(dir)) {
        c.start = CaseStart::Fresh;  // stopped before its first checkpoint: nothing to go on with
        notes.push_back(c.name + ": stopped before its first checkpoint, runs afresh");
      }
    } catch (const InputError& e) {
      throw InputError("sweep --restart: case " + c.name + ": " + e.what() +
                       "; to run this case afresh, remove its directory (--force runs the whole sweep afresh)");
    }
  }
  return notes;
}

void run_sweep(std::vector<SweepCase>& cases, int jobs, bool force) {
  std::optional<GmshReuse> reuse(std::in_place);  // a geometry the cases share meshed once
  for (SweepCase& c : cases) {  // before any case computes (see the header)
    if (c.status != CaseStatus::NotRun || c.config.mesh.file.empty() || stop_signal()) continue;  // kept: Complete
    try {
      c.mesh = make_mesh(c.config);
    } catch (const Interrupted& e) {
      c.status = CaseStatus::Interrupted;
      c.error = e.what();
      c.signal = e.signal;
    } catch (const InputError& e) {
      c.status = CaseStatus::Failed;
      c.error = e.what();
    }
  }
  reuse.reset();
  std::atomic<std::size_t> next{0};
  auto worker = [&]() {
    for (std::size_t k = next++; k < cases.size() && !stop_signal(); k = next++) {
      SweepCase& c = cases[k];
      if (c.status != CaseStatus::NotRun) continue;  // kept (Complete), or its mesh refused
      RunOptions options;
      options.write_files = true;
      options.label = c.name;  // the cases' notes mix on stderr
      options.restart = c.start == CaseStart::Restart;
      options.force = !options.restart && (force || holds_results(c.config.output.directory));
      try {
        c.result = Simulation(c.config, options, std::exchange(c.mesh, std::nullopt)).run();
        c.status = CaseStatus::Complete;
      } catch (const Interrupted& e) {
        c.status = CaseStatus::Interrupted;
        c.error = e.what();
        c.signal = e.signal;
      } catch (const std::exception& e) {
        c.status = CaseStatus::Failed;
        c.error = e.what();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < std::max(1, jobs); ++j) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
}

std::string overlay_command(const std::string& directory, const std::vector<SweepCase>& cases) {
  std::string runs;
  std::error_code ec;  // a directory that cannot be looked at (a name too long there) has no results
  for (const SweepCase& c : cases)  // those with results: not a case never started, or stopped while meshed
    if (std::filesystem::exists(c.config.output.directory + "/curves.csv", ec))
      runs += " " + shell_quoted(c.config.output.directory);
  return runs.empty() ? "" : "tools/plot --overlay " + shell_quoted(directory) + runs;
}

std::string resume_command(const std::string& rccm_path, const std::string& config_file,
                           const std::vector<std::string>& overrides, int jobs, const std::string& directory) {
  std::string command = shell_quoted(rccm_path) + " sweep " + shell_quoted(config_file);
  for (const std::string& o : overrides) command += " --set " + shell_quoted(o);
  return command + " -j " + std::to_string(jobs) + " --restart " + shell_quoted(directory);
}

namespace {

/// The load the summary reports: of the driven loads (one whose value varies in some case: a
/// ramp, a table), the one whose force peaks highest over the complete cases. A support (held
/// at 0) may react at round-off only, or carry the driven load's force back (two bodies, a pile
/// in its soil), and a load held at its value from the start (a confining pressure) peaks at
/// t = 0: either would read as the result. Without a driven load, a held one other than 0;
/// tools/plot --overlay draws the same load.
std::size_t reported_load(const std::vector<SweepCase>& cases) {
  const auto drive = [&](std::size_t k) {  // 2 varies, 1 held at a value other than 0, 0 held at 0
    int level = 0;
    for (const SweepCase& c : cases)
      if (c.status == CaseStatus::Complete && k < c.config.loads.size()) {  // as the plot reads curves.csv
        const TimeFunction& f = c.config.loads[k].amplitude;
        const double T = c.config.time.T;
        std::vector<double> v{f(0.0), f(T)};  // its values over the run: the ends and the corners between
        for (std::size_t j = 0; j < f.t.size(); ++j)
          if (f.t[j] > 0 && f.t[j] < T) v.push_back(f.v[j]);
        for (double x : v) level = std::max(level, x != v.front() ? 2 : x != 0 ? 1 : 0);
      }
    return level;
  };
  std::vector<int> levels(cases.front().config.loads.size());  // the cases' loads are the same
  for (std::size_t k = 0; k < levels.size(); ++k) levels[k] = drive(k);
  const int top = levels.empty() ? 0 : *std::max_element(levels.begin(), levels.end());
  std::size_t load = 0;
  double largest = -1;
  for (const SweepCase& c : cases)
    if (c.status == CaseStatus::Complete)
      for (std::size_t k = 0; k < c.result.peak_force.size(); ++k)
        if (k < levels.size() && levels[k] == top && std::abs(c.result.peak_force[k]) > largest)
          largest = std::abs(c.result.peak_force[k]), load = k;
  return load;
}

}  // namespace

void write_sweep_summary(std::ostream& out, const std::string& directory, const std::vector<SweepAxis>& axes,
                         const std::vector<SweepCase>& cases) {
  // The output times of every case and its T, once each (a sweep of time.T or output.times
  // gives its cases different ones: a case has its figure at its own times only).
  std::vector<double> times;
  for (const SweepCase& c : cases) {
    times.insert(times.end(), c.config.output.times.begin(), c.config.output.times.end());
    times.push_back(c.config.time.T);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return b - a <= 1e-12 * b; }), times.end());
  std::vector<std::string> header = {"case"};
  for (const SweepAxis& a : axes) header.push_back(a.path);
  const std::size_t load = reported_load(cases);
  // The load's label, or its index alone where the cases load different node sets (a sweep of
  // loads.[k].node_set): each row is that case's own load k.
  std::string named = cases.front().config.loads.empty() ? "" : " " + load_label(cases.front().config, load);
  for (const SweepCase& c : cases)
    if (!named.empty() && " " + load_label(c.config, load) != named) named = " L" + std::to_string(load) + " (each case's)";
  header.insert(header.end(), {"status", "peak force" + named + " [N]", "t at peak [s]"});
  const bool solid = cases.front().config.mesh.dim() == 3;  // a debonded area, mm2
  for (double t : times) header.push_back("debonded at t=" + csv_number(t) + (solid ? " [mm2]" : " [mm]"));
  header.insert(header.end(), {"damage dissipation [N mm]", "friction dissipation [N mm]",
                               "energy imbalance (relative)", "steps", "wall [s]", "message"});

  AtomicFile csv_file(directory + "/summary.csv");
  csv_file.stream() << csv_line(header) << "\n";
  // The table: the same figures, "-" where a case did not complete.
  char buf[64];
  std::snprintf(buf, sizeof buf, "%-28s %-12s", "case", "status");
  out << buf;
  std::vector<std::string> labels = {"peak F [N]", "t peak [s]"};
  for (double t : times) labels.push_back("debond@" + csv_number(t));
  labels.insert(labels.end(), {"damage [N mm]", "friction", "imbalance", "steps", "wall [s]"});
  for (const std::string& label : labels) {
    std::snprintf(buf, sizeof buf, " %14.14s", label.c_str());
    out << buf;
  }
  out << "\n";
  for (const SweepCase& c : cases) {
    const RunResult& r = c.result;
    const bool complete = c.status == CaseStatus::Complete;
    std::vector<std::string> row = {c.name};
    row.insert(row.end(), c.values.begin(), c.values.end());
    row.push_back(case_status_name(c.status));
    // Empty where the case has no such figure (not complete, or no snapshot at that time).
    std::vector<std::optional<double>> figures(2 + times.size() + 5);
    if (complete) {
      figures[0] = load < r.peak_force.size() ? r.peak_force[load] : 0.0;
      figures[1] = load < r.peak_time.size() ? r.peak_time[load] : 0.0;
      for (std::size_t k = 0; k < times.size(); ++k)
        for (const Snapshot& s : r.snapshots)
          if (std::abs(s.t - times[k]) <= 1e-12 * times[k]) figures[2 + k] = s.debonded_length;
      const double last[] = {r.energy.damage_dissipation, r.energy.friction_dissipation, r.energy.relative_error(),
                             double(r.integrator.steps), r.wall_seconds};
      std::copy(std::begin(last), std::end(last), figures.end() - 5);
    }
    // The message: why a case did not complete, or the warnings of one that did (an
    // unstable Euler, a doubtful interface): a complete row is not a trusted one.
    std::string message = c.error;
    if (complete && c.config.integrator.method == Method::RateIndependent)  // as report.txt says it
      message = "rate-independent (alpha = 0): the imbalance is the work released in snap-throughs and the steps' "
                "error (docs/MODEL.md s3)";
    if (complete)
      for (const std::string& w : r.warnings) message += (message.empty() ? "warning: " : "; warning: ") + w;
    message = one_line(message);
    for (const std::optional<double>& f : figures) row.push_back(f ? csv_number(*f) : "");
    row.push_back(message);
    csv_file.stream() << csv_line(row) << "\n";

    std::snprintf(buf, sizeof buf, "%-28s %-12s", c.name.c_str(), case_status_name(c.status));
    out << buf;
    for (const std::optional<double>& f : figures) {
      if (f) std::snprintf(buf, sizeof buf, " %14.6g", *f);
      out << (f ? std::string(buf) : std::string(14, ' ') + "-");
    }
    out << (message.empty() ? "" : "   " + message) << "\n";
  }
  csv_file.commit();
}

void write_sweep_jobs(const std::string& directory, const std::vector<SweepCase>& cases, const std::string& rccm_path,
                      const std::string& config_file) {
  // Absolute paths: a job runs from wherever the cluster's script starts it. A program name
  // without a '/' was found on the PATH and is left for the PATH to find again.
  const auto absolute = [](const std::string& path) { return std::filesystem::absolute(path).lexically_normal().string(); };
  const std::string program = rccm_path.find('/') == std::string::npos ? rccm_path : absolute(rccm_path);
  AtomicFile jobs_file(directory + "/jobs.txt");
  for (const SweepCase& c : cases) {
    jobs_file.stream() << shell_quoted(program) << " run " << shell_quoted(absolute(config_file)) << " -q";
    for (const std::string& o : c.overrides) jobs_file.stream() << " --set " << shell_quoted(o);
    jobs_file.stream() << " -o " << shell_quoted(absolute(directory + "/" + c.name)) << "\n";
  }
  jobs_file.commit();
}

}  // namespace rccm
