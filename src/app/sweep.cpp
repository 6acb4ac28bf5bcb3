#include "rccm/app/sweep.hpp"

#include "rccm/io/atomic_file.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/io/config_reader.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <thread>

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

}  // namespace

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
}

std::vector<SweepCase> make_sweep_cases(const std::string& config_file, const std::vector<std::string>& fixed,
                                        const std::vector<SweepAxis>& axes, const std::string& directory) {
  std::vector<SweepCase> cases(1);
  for (const SweepAxis& axis : axes) {
    std::vector<SweepCase> grown;
    for (const SweepCase& c : cases)
      for (const std::string& v : axis.values) {
        SweepCase n = c;
        n.name += (n.name.empty() ? "" : "_") + leaf(axis.path) + "=" + v;
        n.overrides.push_back(axis.path + "=" + v);
        grown.push_back(n);
      }
    cases = grown;
  }
  for (SweepCase& c : cases) {
    c.overrides.insert(c.overrides.begin(), fixed.begin(), fixed.end());
    std::vector<std::string> all = c.overrides;
    all.push_back("output.directory=\"" + directory + "/" + c.name + "\"");
    for (const std::string& o : c.overrides)
      if (o.rfind("interface.alpha=", 0) == 0 && std::strtod(o.c_str() + 16, nullptr) == 0.0) {
        all.push_back("integrator.method=\"rate-independent\"");  // alpha = 0: the limit (docs/MODEL.md s3)
        c.overrides.push_back(all.back());
      }
    c.config = load_config(config_file, all);
  }
  return cases;
}

void run_sweep(std::vector<SweepCase>& cases, int jobs, bool force) {
  std::atomic<std::size_t> next{0};
  auto worker = [&]() {
    for (std::size_t k = next++; k < cases.size(); k = next++) {
      RunOptions options;
      options.write_files = true;
      options.force = force;
      try {
        cases[k].result = Simulation(cases[k].config, options).run();
      } catch (const std::exception& e) {
        cases[k].error = e.what();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < std::max(1, jobs); ++j) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
}

void write_sweep_summary(std::ostream& out, const std::string& directory, const std::vector<SweepCase>& cases,
                         const std::string& rccm_path, const std::string& config_file) {
  AtomicFile csv_file(directory + "/summary.csv"), jobs_file(directory + "/jobs.txt");
  std::ostream &csv = csv_file.stream(), &jobs = jobs_file.stream();
  csv << "case,peak force [N],t at peak [s]";
  out << "case                          peak force [N]  t peak [s]";
  for (const Snapshot& s : cases.front().result.snapshots) {
    csv << ",debonded at t=" << s.t << " [mm]";
    char h[40];
    std::snprintf(h, sizeof h, "  debond@%-6g", s.t);
    out << h;
  }
  csv << ",damage dissipation [N mm],friction dissipation [N mm],energy imbalance (relative),steps,wall [s],error\n";
  out << "  damage diss.  friction diss.  energy err   wall [s]\n";
  char buf[128];
  for (const SweepCase& c : cases) {
    const RunResult& r = c.result;
    const double peak = r.peak_force.empty() ? 0.0 : r.peak_force[0], tp = r.peak_time.empty() ? 0.0 : r.peak_time[0];
    csv << c.name << "," << peak << "," << tp;
    std::snprintf(buf, sizeof buf, "%-28s %15.6g %11.4g", c.name.c_str(), peak, tp);
    out << buf;
    for (const Snapshot& s : r.snapshots) {
      csv << "," << s.debonded_length;
      std::snprintf(buf, sizeof buf, "  %12.4g", s.debonded_length);
      out << buf;
    }
    csv << "," << r.energy.damage_dissipation << "," << r.energy.friction_dissipation << ","
        << r.energy.relative_error() << "," << r.integrator.steps << "," << r.wall_seconds << ","
        << (c.error.empty() ? "" : "\"failed\"") << "\n";
    std::snprintf(buf, sizeof buf, "  %12.5g  %14.5g  %10.2e %10.3f", r.energy.damage_dissipation,
                  r.energy.friction_dissipation, r.energy.relative_error(), r.wall_seconds);
    out << buf << (c.error.empty() ? "" : "   FAILED: " + c.error) << "\n";

    jobs << rccm_path << " run " << config_file << " -q";
    for (const std::string& o : c.overrides) jobs << " --set '" << o << "'";
    jobs << " --set 'output.directory=\"" << directory << "/" << c.name << "\"'\n";
  }
  csv_file.commit();
  jobs_file.commit();
}

}  // namespace rccm
