#include "rccm/app/bench.hpp"

#include "rccm/io/atomic_file.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/io/config_reader.hpp"
#include "rccm/io/csv.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace rccm {

namespace {

/// Resets the kernel's peak-RSS counter of this process (Linux: clear_refs 5).
void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5"; }

/// Peak resident memory since the last reset, MB (VmHWM of /proc/self/status; 0 elsewhere).
double peak_memory_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

struct Figures {
  double setup, solves, sweeps_mean, us_per_solve, us_per_body_solve, ms_per_step, wall;
};

Figures figures(const RunResult& r) {
  const double n = std::max(1L, r.solves.contact_solves);
  return {r.setup_seconds,
          double(r.solves.contact_solves),
          double(r.solves.sweeps) / n,
          1e6 * r.solves.seconds / n,
          1e6 * r.body_solve_seconds / std::max(1L, r.body_solves),
          1e3 * (r.wall_seconds - r.setup_seconds) / std::max(1L, r.integrator.steps),
          r.wall_seconds};
}

std::string speedup(const BenchRow& row) {
  if (row.bench.paper_seconds <= 0) return "";
  char s[32];
  std::snprintf(s, sizeof s, "%.0f", row.bench.paper_seconds / row.result.wall_seconds);
  return s;
}

}  // namespace

std::vector<BenchCase> paper_cases(const std::string& config_dir) {
  const std::string b1 = config_dir + "/b1.cfg", b2 = config_dir + "/b2.cfg";
  const std::vector<std::string> euler = {"integrator.method=euler", "time.steps=210"};
  std::vector<std::string> b1_jacobi = euler, b2_jacobi = euler;
  b1_jacobi.push_back("solver.form=jacobi");
  b2_jacobi.push_back("solver.form=jacobi");
  b2_jacobi.push_back("solver.relaxation=0.2");  // B2's coupled W0: Jacobi diverges without it
  return {{"B1 arkode", load_config(b1), 66.8},
          {"B1 euler-210", load_config(b1, euler), 66.8},
          {"B1 euler-210 jacobi", load_config(b1, b1_jacobi), 66.8},
          {"B2 arkode", load_config(b2), 136.5},
          {"B2 euler-210", load_config(b2, euler), 136.5},
          {"B2 euler-210 jacobi", load_config(b2, b2_jacobi), 136.5}};
}

namespace {

/// A scale case: `cfg` run over [0, T] of its own loading (the load's time function keeps its
/// absolute times, the steps their bound), no output times, the body solved by `linear`.
BenchCase time_window(const std::string& name, Config cfg, double T, LinearSolver linear) {
  cfg.integrator.max_step = cfg.integrator.largest_step(cfg.time.T);
  cfg.time.T = T;
  cfg.output.times.clear();
  cfg.solver.linear.kind = linear;
  return {name, cfg, 0.0};
}

}  // namespace

std::vector<BenchCase> scale_cases(const std::string& config_dir, int levels, double T, LinearSolver linear) {
  std::vector<BenchCase> cases;
  for (int k = 0; k < levels; ++k) {
    const int f = 1 << k;
    cases.push_back(time_window("B1 x" + std::to_string(f),
                                load_config(config_dir + "/b1.cfg", {"mesh.nx=" + std::to_string(32 * f),
                                                                     "mesh.ny=" + std::to_string(2 * f)}),
                                T, linear));
  }
  return cases;
}

std::vector<BenchCase> corner_peel_cases(const std::string& config_dir, int levels, double T, LinearSolver linear) {
  std::vector<BenchCase> cases;
  const int sides[] = {8, 12, 16, 24, 32, 45, 64};
  for (int k = 0; k < levels && k < 7; ++k) {
    const std::string n = std::to_string(sides[k]);
    cases.push_back(time_window("corner peel " + n + "x" + n,
                                load_config(config_dir + "/corner-peel.cfg", {"mesh.nx=" + n, "mesh.nz=" + n, "mesh.ny=2"}),
                                T, linear));
  }
  return cases;
}

BenchRow run_bench_case(const BenchCase& c) {
  reset_peak_memory();
  BenchRow row{c, Simulation(c.config).run(), 0.0};
  row.peak_rss_mb = peak_memory_mb();
  return row;
}

void print_bench_header(std::ostream& out) {
  char line[512];
  std::snprintf(line, sizeof line, "%-20s %9s %8s %6s %9s %11s %10s %10s %9s %9s %9s %8s %8s\n", "case", "unknowns",
                "contact", "steps", "solves", "sweeps/sol", "us/solve", "us/body", "ms/step", "setup s", "wall s",
                "peak MB", "paper/x");
  out << line;
}

void print_bench_row(std::ostream& out, const BenchRow& row) {
  const RunResult& r = row.result;
  const Figures f = figures(r);
  char line[512];
  std::snprintf(line, sizeof line, "%-20s %9d %8d %6ld %9ld %6.2f/%-4d %10.1f %10.1f %9.3f %9.4f %9.3f %8.1f %8s\n",
                row.bench.name.c_str(), r.dofs, r.contact_nodes, r.integrator.steps, r.solves.contact_solves,
                f.sweeps_mean, r.solves.max_sweeps, f.us_per_solve, f.us_per_body_solve, f.ms_per_step, f.setup, f.wall,
                row.peak_rss_mb, speedup(row).c_str());
  out << line << std::flush;
}

void print_growth(std::ostream& out, const std::vector<BenchRow>& rows) {
  if (rows.size() < 2) return;
  // Least-squares slope of log(value) against log(size).
  const auto slope = [&](auto size, auto value) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(rows.size());
    for (const BenchRow& row : rows) {
      const double x = std::log(double(size(row.result))), y = std::log(std::max(value(row), 1e-12));
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
  };
  const auto unknowns = [](const RunResult& r) { return r.dofs; };
  const auto contact_nodes = [](const RunResult& r) { return r.contact_nodes; };
  const auto setup = [](const BenchRow& r) { return figures(r.result).setup; };
  const auto per_solve = [](const BenchRow& r) { return figures(r.result).us_per_solve; };
  const auto per_body_solve = [](const BenchRow& r) { return figures(r.result).us_per_body_solve; };
  const auto per_step = [](const BenchRow& r) { return figures(r.result).ms_per_step; };
  const auto memory = [](const BenchRow& r) { return r.peak_rss_mb; };
  char line[512];
  std::snprintf(line, sizeof line,
                "growth exponents against unknowns: setup %.2f, per contact solve %.2f, per body solve %.2f, per step "
                "%.2f, memory %.2f\n"
                "growth exponents against contact nodes: setup %.2f, per contact solve %.2f, per body solve %.2f, per "
                "step %.2f, memory %.2f\n",
                slope(unknowns, setup), slope(unknowns, per_solve), slope(unknowns, per_body_solve),
                slope(unknowns, per_step), slope(unknowns, memory), slope(contact_nodes, setup),
                slope(contact_nodes, per_solve), slope(contact_nodes, per_body_solve), slope(contact_nodes, per_step),
                slope(contact_nodes, memory));
  out << line;
}

namespace {

/// The figures of a row, named as in the CSV header and the JSON keys.
std::vector<std::pair<std::string, double>> named_figures(const BenchRow& row) {
  const RunResult& r = row.result;
  const Figures f = figures(r);
  return {{"unknowns", r.dofs},
          {"contact_nodes", r.contact_nodes},
          {"steps", double(r.integrator.steps)},
          {"rejected", double(r.integrator.rejected)},
          {"contact_solves", double(r.solves.contact_solves)},
          {"sweeps_mean", f.sweeps_mean},
          {"sweeps_max", r.solves.max_sweeps},
          {"us_per_solve", f.us_per_solve},
          {"us_per_body_solve", f.us_per_body_solve},
          {"ms_per_step", f.ms_per_step},
          {"setup_s", f.setup},
          {"wall_s", f.wall},
          {"peak_rss_mb", row.peak_rss_mb},
          {"paper_s", row.bench.paper_seconds}};
}

}  // namespace

void write_bench_csv(const std::string& path, const std::vector<BenchRow>& rows) {
  AtomicFile file(path);
  std::vector<std::string> header = {"case"};
  for (const auto& [name, value] : named_figures(rows.front())) header.push_back(name);
  file.stream() << csv_line(header) << "\n";
  for (const BenchRow& row : rows) {
    std::vector<std::string> line = {row.bench.name};
    for (const auto& [name, value] : named_figures(row)) line.push_back(csv_number(value));
    file.stream() << csv_line(line) << "\n";
  }
  file.commit();
}

void write_bench_json(const std::string& path, const std::vector<BenchRow>& rows) {
  nlohmann::json table = nlohmann::json::array();
  for (const BenchRow& row : rows) {
    nlohmann::json entry = {{"case", row.bench.name}};
    for (const auto& [name, value] : named_figures(row)) entry[name] = value;
    table.push_back(entry);
  }
  AtomicFile file(path);
  file.stream() << table.dump(2) << "\n";
  file.commit();
}

}  // namespace rccm
