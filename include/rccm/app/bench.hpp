// `rccm bench`: the benchmark harness. B1 and B2 with each integrator and both sweep forms,
// timed against the paper's totals (Tables 1-2), and the refined B1 family for scaling
// (docs/PERFORMANCE.md, "The contact step and the integrator" and "Scale").
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/app/simulation.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace rccm {

struct BenchCase {
  std::string name;
  Config config;
  double paper_seconds = 0;  // the paper's total for this benchmark (0: none)
};

struct BenchRow {
  BenchCase bench;
  RunResult result;
  double peak_rss_mb = 0;  // peak resident memory of this case (Linux VmHWM, reset per case)
};

/// B1 and B2 (config_dir/b1.cfg, b2.cfg): ARKODE with its default tolerances and Euler-210,
/// Gauss-Seidel, and the paper's Jacobi form with Euler-210.
std::vector<BenchCase> paper_cases(const std::string& config_dir);

/// B1 refined 2^k times in each direction, k = 0 .. levels-1, run over [0, T] only (the
/// same loading rate), ARKODE default tolerances.
/// `linear`: the body's solver of every case (solver.linear).
std::vector<BenchCase> scale_cases(const std::string& config_dir, int levels, double T, LinearSolver linear);

/// The 3D family: the corner peel (config_dir/corner-peel.cfg) on n x 2 x n H8 cells, n = 8,
/// 12, 16, 24, 32, 45, 64 (the first `levels`: 81 to 4225 contact nodes), over [0, T] as above.
std::vector<BenchCase> corner_peel_cases(const std::string& config_dir, int levels, double T, LinearSolver linear);

BenchRow run_bench_case(const BenchCase& c);

/// The table on `out`: its header, then one row per case (us/solve: time inside the contact
/// solves per solve; ms/step: run time after setup per accepted step; paper/x: the paper's
/// total over ours).
void print_bench_header(std::ostream& out);
void print_bench_row(std::ostream& out, const BenchRow& row);

/// Growth exponents (least squares in log-log against the number of unknowns) of setup time,
/// time per contact solve, time per accepted step and memory.
void print_growth(std::ostream& out, const std::vector<BenchRow>& rows);

void write_bench_csv(const std::string& path, const std::vector<BenchRow>& rows);
void write_bench_json(const std::string& path, const std::vector<BenchRow>& rows);

}  // namespace rccm
