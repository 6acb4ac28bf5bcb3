// Result files: what is written equals what the solver computed, to the printed precision.
#include "helpers.hpp"
#include "rccm/base/config.hpp"
#include "rccm/app/simulation.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rccm;
namespace fs = std::filesystem;

namespace {

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(cell);
    rows.push_back(row);
  }
  return rows;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t j = 0; j < header.size(); ++j)
    if (header[j] == name) return j;
  FAIL("no column " << name);
  return 0;
}

}  // namespace

TEST_CASE("CSV round trip: interface, history and curves hold the solver's values", "[output]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_output";
  fs::remove_all(dir);
  Config cfg = load_config(std::string(RCCM_SOURCE_DIR) + "/config/b1.cfg",
                           {"integrator.method=euler", "output.directory=\"" + dir.string() + "\""});
  RunOptions options;
  options.write_files = true;
  const RunResult r = Simulation(cfg, options).run();

  // Interface files: one per output time and T, every field of every node.
  REQUIRE(r.snapshots.size() == 3);
  for (const Snapshot& s : r.snapshots) {
    std::ostringstream name;
    name << "interface_t" << s.t << ".csv";
    const auto rows = read_csv((dir / name.str()).string());
    REQUIRE(rows.size() == static_cast<std::size_t>(s.beta.size()) + 1);
    const auto& h = rows[0];
    for (Eigen::Index i = 0; i < s.beta.size(); ++i) {
      const auto& row = rows[i + 1];
      CHECK(std::stod(row[column(h, "beta")]) == Approx(s.beta[i]).epsilon(1e-10).margin(1e-300));
      CHECK(std::stod(row[column(h, "u_n [mm]")]) == Approx(s.u[2 * i + 1]).epsilon(1e-10).margin(1e-300));
      CHECK(std::stod(row[column(h, "u_t [mm]")]) == Approx(s.u[2 * i]).epsilon(1e-10).margin(1e-300));
      CHECK(std::stod(row[column(h, "Rbar_n [N]")]) == Approx(s.Rbar[2 * i + 1]).epsilon(1e-10).margin(1e-300));
      CHECK(std::stod(row[column(h, "Rbar_t [N]")]) == Approx(s.Rbar[2 * i]).epsilon(1e-10).margin(1e-300));
    }
  }
  // History: a row per accepted step (and the initial state), the watched point B = node 0.
  const auto history = read_csv((dir / "history.csv").string());
  REQUIRE(history.size() == r.steps.size() + 1);
  const auto& last = history.back();
  CHECK(std::stod(last[column(history[0], "t [s]")]) == Approx(10.0));
  CHECK(std::stod(last[column(history[0], "B beta")]) == Approx(r.snapshots.back().beta[0]).epsilon(1e-10).margin(1e-300));
  // Curves: the last row carries the run's energy terms.
  const auto curves = read_csv((dir / "curves.csv").string());
  REQUIRE(curves.size() == r.steps.size() + 1);
  CHECK(std::stod(curves.back()[column(curves[0], "external work [N mm]")]) ==
        Approx(r.energy.external_work).epsilon(1e-10));
  CHECK(std::stod(curves.back()[column(curves[0], "L0 top_left.y value [mm]")]) == Approx(0.3).epsilon(1e-12));
  // The report exists in both forms.
  CHECK(fs::file_size(dir / "report.txt") > 0);
  CHECK(fs::file_size(dir / "report.json") > 0);
  CHECK(fs::exists(dir / "results.pvd"));
}
