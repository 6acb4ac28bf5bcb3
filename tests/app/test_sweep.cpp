// rccm sweep: the grid of cases, the rate-independent case, and a physical check of the
// alpha study: more viscosity, higher peak peel force (docs/MODEL.md s3, docs/BENCHMARKS.md B1).
#include "helpers.hpp"
#include "rccm/app/stop_request.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/app/sweep.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace rccm;
namespace fs = std::filesystem;

namespace {
const std::string b1 = std::string(RCCM_SOURCE_DIR) + "/config/b1.cfg";

std::size_t lines(const fs::path& p) {
  std::ifstream in(p);
  std::size_t n = 0;
  for (std::string l; std::getline(in, l);) ++n;
  return n;
}
}  // namespace

TEST_CASE("sweep settings: lists are axes, arrays and single values are fixed", "[sweep]") {
  std::vector<SweepAxis> axes;
  std::vector<std::string> fixed;
  split_sweep_settings({"interface.alpha=0,0.1,1", "output.times=[1.0,2.0]", "interface.mu=0.3", "solver.form=jacobi"},
                       axes, fixed);
  REQUIRE(axes.size() == 1);
  CHECK(axes[0].path == "interface.alpha");
  CHECK(axes[0].values == std::vector<std::string>{"0", "0.1", "1"});
  CHECK(fixed == std::vector<std::string>{"output.times=[1.0,2.0]", "interface.mu=0.3", "solver.form=jacobi"});
  // A swept setting given again, or a value listed twice: refused, not one silently dropped.
  const auto split = [](const std::vector<std::string>& items) {
    std::vector<SweepAxis> a;
    std::vector<std::string> f;
    split_sweep_settings(items, a, f);
  };
  CHECK_THROWS_WITH(split({"interface.alpha=0.1,1", "interface.alpha=5"}),
                    Catch::Contains("sweep: --set interface.alpha is given more than once"));
  CHECK_THROWS_WITH(split({"interface.alpha=5", "interface.alpha=0.1,1"}),
                    Catch::Contains("sweep: --set interface.alpha is given more than once"));
  CHECK_THROWS_WITH(split({"interface.alpha=1,2,1"}), Catch::Contains("lists 1 twice"));
  // The same number written twice otherwise: two cases of one run.
  CHECK_THROWS_WITH(split({"interface.alpha=0.1,0.10"}), Catch::Contains("lists 0.1 and 0.10, the same number"));
  CHECK_THROWS_WITH(split({"interface.alpha=1e-1,2,0.1"}), Catch::Contains("lists 1e-1 and 0.1, the same number"));
  CHECK_THROWS_WITH(split({"interface.alpha=0.1 ,0.10"}), Catch::Contains("the same number"));
  // output.directory: the sweep gives each case its own (DIR/<case>), a list of it would be cases alike.
  CHECK_THROWS_WITH(split({"interface.alpha=1,2", "output.directory=x1,x2"}),
                    Catch::Contains("sweep: --set output.directory cannot be swept: the sweep decides each case's directory") &&
                        Catch::Contains("-o DIR chooses the sweep's directory, their parent"));
  CHECK_NOTHROW(split({"interface.alpha=1,2", "output.directory=x1"}));  // one value: the sweep's directory is x1-sweep
  CHECK_NOTHROW(split({"mesh.element=\"T3\",\"Q4\"", "interface.alpha=0.1,0.11", "interface.mu=0.1,0.1x"}));
  CHECK_NOTHROW(split({"interface.alpha=1,2", "interface.mu=0.1,0.2", "time.T=5.0"}));
}

TEST_CASE("sweep cases: a grid of two axes, alpha = 0 is the rate-independent limit", "[sweep]") {
  const std::vector<SweepAxis> axes{{"interface.alpha", {"0", "1"}}, {"interface.mu", {"0.1", "0.3"}}};
  const std::vector<SweepCase> cases = make_sweep_cases(b1, {}, axes, "/tmp/rccm_sweep_grid");
  REQUIRE(cases.size() == 4);
  CHECK(cases[0].name == "alpha=0_mu=0.1");
  CHECK(cases[3].name == "alpha=1_mu=0.3");
  CHECK(cases[0].config.integrator.method == Method::RateIndependent);
  CHECK(cases[3].config.integrator.method == Method::Arkode);
  CHECK(cases[3].config.interfaces[0].mu == 0.3);
  CHECK(cases[1].config.output.directory == "/tmp/rccm_sweep_grid/alpha=0_mu=0.3");
}

TEST_CASE("sweep cases: a value with a path in it names one directory of the sweep, not a nest", "[sweep]") {
  const std::string dcb = test::shipped("dcb.cfg");
  const std::vector<SweepCase> cases =
      make_sweep_cases(dcb, {}, {{"mesh.file", {"\"dcb.geo\"", "\"../config/dcb.geo\""}}}, "/tmp/rccm_sweep_paths");
  REQUIRE(cases.size() == 2);
  CHECK(cases[1].name == "file=\".._config_dcb.geo\"");
  for (const SweepCase& c : cases) CHECK(fs::path(c.config.output.directory).parent_path() == "/tmp/rccm_sweep_paths");
  CHECK(fs::equivalent(cases[1].config.mesh.file, test::shipped("dcb.geo")));  // the value itself is unchanged
  // Two values that differ only there would share a directory.
  CHECK_THROWS_WITH(make_sweep_cases(dcb, {}, {{"mesh.file", {"\"a/dcb.geo\"", "\"a_dcb.geo\""}}}, "/tmp/rccm_sweep_paths"),
                    Catch::Contains("two cases would share the directory file=\"a_dcb.geo\""));
}

TEST_CASE("sweep cases: a case directory name longer than a file system allows is refused before any case runs", "[sweep]") {
  // A case's directory is one name: at most 255 bytes (NAME_MAX). "alpha=" and 249 characters is 255.
  const std::string fits = "0." + std::string(247, '1'), too_long = fits + "1";
  const std::string dir = (fs::temp_directory_path() / "rccm_sweep_long_names").string();
  fs::remove_all(dir);
  const std::vector<SweepCase> cases = make_sweep_cases(b1, {}, {{"interface.alpha", {"0.1", fits}}}, dir);
  REQUIRE(cases.size() == 2);
  CHECK(cases[1].name.size() == 255);
  CHECK_THROWS_WITH(make_sweep_cases(b1, {}, {{"interface.alpha", {"0.1", too_long}}}, dir),
                    Catch::Contains("sweep: --set interface.alpha=0.1111") && Catch::Contains("(250 characters)") &&
                        Catch::Contains("its case's directory name would be 256 bytes, more than the 255 a file system allows"));
  // Of two axes, the longer value is named (the name joins both).
  CHECK_THROWS_WITH(make_sweep_cases(b1, {}, {{"interface.mu", {"0.1", "0.3"}}, {"interface.alpha", {"1", fits}}}, dir),
                    Catch::Contains("sweep: --set interface.alpha=0.1111") && Catch::Contains("would be 262 bytes"));
  CHECK_FALSE(fs::exists(dir));
}

TEST_CASE("the overlay command names the cases with results and passes over a directory it cannot look at", "[sweep]") {
  // A case directory too long for the file system it is on (eCryptfs allows 143 bytes in a
  // name): the case failed, and looking for its curves.csv must not end the sweep.
  const fs::path dir = fs::temp_directory_path() / "rccm_sweep_overlay";
  fs::remove_all(dir);
  std::vector<SweepCase> cases = make_sweep_cases(b1, {}, {{"interface.alpha", {"1", "2"}}}, dir.string());
  REQUIRE(cases.size() == 2);
  fs::create_directories(dir / "alpha=2");
  std::ofstream((dir / "alpha=2" / "curves.csv").string()) << "t [s]\n";
  cases[0].config.output.directory = (dir / std::string(300, 'a')).string();
  CHECK(overlay_command(dir.string(), cases) == "tools/plot --overlay '" + dir.string() + "' '" + (dir / "alpha=2").string() + "'");
  fs::remove_all(dir);
}

TEST_CASE("alpha study on B1: three cases, peak peel force increases with alpha", "[sweep]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_sweep";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<SweepAxis> axes = {{"interface.alpha", {"1", "10", "100"}}};
  std::vector<SweepCase> cases = make_sweep_cases(b1, {}, axes, dir.string());
  run_sweep(cases, 2);
  std::ostringstream table;
  write_sweep_summary(table, dir.string(), axes, cases);
  write_sweep_jobs(dir.string(), cases, "rccm", b1);
  CHECK(lines(dir / "summary.csv") == 4);  // header and three rows
  CHECK(lines(dir / "jobs.txt") == 3);
  for (const SweepCase& c : cases) {
    INFO(c.name << ": " << c.error);
    REQUIRE(c.error.empty());
    CHECK(fs::exists(dir / c.name / "report.txt"));
  }
  const double p1 = cases[0].result.peak_force[0], p10 = cases[1].result.peak_force[0],
               p100 = cases[2].result.peak_force[0];
  INFO("peak forces " << p1 << " " << p10 << " " << p100);
  CHECK(p1 < p10);
  CHECK(p10 < p100);
  // A more viscous interface debonds less by T.
  CHECK(cases[2].result.snapshots.back().debonded_length < cases[0].result.snapshots.back().debonded_length);
}

TEST_CASE("a sweep of time.T: a column for each case's T and output times, each filled where the case has it", "[sweep]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_sweep_swept_T";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<SweepAxis> axes = {{"time.T", {"2", "4"}}, {"output.times", {"[1.0]", "[1.0, 1.5]"}}};
  std::vector<SweepCase> cases = make_sweep_cases(b1, {}, axes, dir.string());
  REQUIRE(cases.size() == 4);
  run_sweep(cases, 1);
  std::ostringstream table;
  write_sweep_summary(table, dir.string(), axes, cases);
  const test::CsvTable summary = test::read_csv((dir / "summary.csv").string());
  const std::vector<double> times = {1.0, 1.5, 2.0, 4.0};
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const test::CsvTable curves = test::read_csv((dir / cases[k].name / "curves.csv").string());
    const std::vector<double> t = curves.numbers("t [s]"), length = curves.numbers("debonded length [mm]");
    const double T = cases[k].config.time.T;
    const std::vector<double>& own = cases[k].config.output.times;
    for (double time : times) {
      const auto column = std::find(summary.header.begin(), summary.header.end(), "debonded at t=" + csv_number(time) + " [mm]");
      REQUIRE(column != summary.header.end());
      const std::string cell = summary.rows[k][std::size_t(column - summary.header.begin())];
      INFO(cases[k].name << " at t = " << time);
      const bool has = time == T || std::find(own.begin(), own.end(), time) != own.end();
      CHECK(cell.empty() == !has);
      if (has && !cell.empty())
        CHECK(std::stod(cell) == Approx(length[std::find(t.begin(), t.end(), time) - t.begin()]).epsilon(1e-9));
    }
  }
  CHECK(summary.header.size() == 1 + axes.size() + 3 + times.size() + 6);  // t = 1, 1.5, 2, 4 once each
  fs::remove_all(dir);
}

TEST_CASE("a sweep whose output times end at T: one column for T, each cell the case's own debonded length", "[sweep]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_sweep_T";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<SweepAxis> axes = {{"interface.alpha", {"1", "10"}}};
  std::vector<SweepCase> cases = make_sweep_cases(b1, {"output.times=[3.571, 10.0]"}, axes, dir.string());
  run_sweep(cases, 1);
  std::ostringstream table;
  write_sweep_summary(table, dir.string(), axes, cases);
  const test::CsvTable summary = test::read_csv((dir / "summary.csv").string());
  CHECK(std::count(summary.header.begin(), summary.header.end(), "debonded at t=10 [mm]") == 1);
  REQUIRE(summary.rows.size() == 2);
  const auto column = [&](const std::string& name) {
    return std::size_t(std::find(summary.header.begin(), summary.header.end(), name) - summary.header.begin());
  };
  REQUIRE(column("debonded at t=3.571 [mm]") < summary.header.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    // The case's curves.csv at its output times (its last line is T).
    const test::CsvTable curves = test::read_csv((dir / cases[k].name / "curves.csv").string());
    const std::vector<double> t = curves.numbers("t [s]"), length = curves.numbers("debonded length [mm]");
    const auto at = [&](double time) { return length[std::find(t.begin(), t.end(), time) - t.begin()]; };
    CHECK(at(10.0) > 0);
    CHECK(std::stod(summary.rows[k][column("debonded at t=10 [mm]")]) == Approx(at(10.0)).epsilon(1e-9));
    CHECK(std::stod(summary.rows[k][column("debonded at t=3.571 [mm]")]) == Approx(at(3.571)).epsilon(1e-9));
  }
  fs::remove_all(dir);
}

TEST_CASE("a sweep reports the driven load's peak, not a support's that carries it back", "[sweep]") {
  // Two glued bodies, the base held and the top pulled: the base's reaction is the pull's force
  // (and by round-off may exceed it); a support listed first may also react harder than the
  // pull. The summary names the driven load, a displacement other than 0 (tools/plot's overlay
  // the same: tests/check_overlay.sh).
  const fs::path dir = fs::temp_directory_path() / "rccm_test_sweep_driven";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<SweepAxis> axes = {{"interface.alpha", {"1", "10"}}};
  std::vector<SweepCase> cases = make_sweep_cases(
      b1, {"loads=({node_set=\"top_right\";type=\"displacement\";component=\"x\";value=0.0;},"
           "{node_set=\"top_left\";type=\"displacement\";component=\"y\";value=0.3;})"},
      axes, dir.string());
  for (SweepCase& c : cases) {
    c.status = CaseStatus::Complete;
    c.result.peak_force = {-700.0 - c.values[0].size(), 650.0};  // the support above the pull
    c.result.peak_time = {4.0, 5.0};
  }
  std::ostringstream table;
  write_sweep_summary(table, dir.string(), axes, cases);
  const test::CsvTable summary = test::read_csv((dir / "summary.csv").string());
  CHECK(summary.header.at(3) == "peak force L1 top_left.y [N]");
  CHECK(summary.rows.at(0).at(3) == "650");
  CHECK(summary.rows.at(1).at(4) == "5");
  // Nothing driven (every load held at 0): the largest force, as before (here the second load's).
  for (SweepCase& c : cases) {
    c.config.loads[1].amplitude.v.assign(c.config.loads[1].amplitude.v.size(), 0.0);
    c.result.peak_force = {-100.0, 650.0};
  }
  write_sweep_summary(table, dir.string(), axes, cases);
  CHECK(test::read_csv((dir / "summary.csv").string()).header.at(3) == "peak force L1 top_left.y [N]");
  // A load held at its value from the start (a confining pressure, peaking at t = 0) beside a
  // driven one: the driven one, though the held one's force is larger (the audit's shear test
  // reported its pressure); without a driven load, the held one, though a support's is larger.
  for (SweepCase& c : cases) {
    c.config.loads[0].amplitude = {{0.0, c.config.time.T, 2 * c.config.time.T}, {5.0, 5.0, 20.0}};  // held to T
    c.config.loads[1].amplitude.v = {0.0, 0.3};
    c.result.peak_force = {-900.0, 650.0};
  }
  write_sweep_summary(table, dir.string(), axes, cases);
  CHECK(test::read_csv((dir / "summary.csv").string()).header.at(3) == "peak force L1 top_left.y [N]");
  for (SweepCase& c : cases) {
    c.config.loads[1].amplitude.v.assign(c.config.loads[1].amplitude.v.size(), 0.0);
    c.result.peak_force = {-100.0, 650.0};
  }
  write_sweep_summary(table, dir.string(), axes, cases);
  CHECK(test::read_csv((dir / "summary.csv").string()).header.at(3) == "peak force L0 top_right.x [N]");
  // A sweep of the load's node set: no one set names the column (the audit's header named the
  // first case's set above the second case's peak on another).
  cases[1].config.loads[0].node_set = "upper";
  write_sweep_summary(table, dir.string(), axes, cases);
  CHECK(test::read_csv((dir / "summary.csv").string()).header.at(3) == "peak force L0 (each case's) [N]");
  fs::remove_all(dir);
}

TEST_CASE("a sweep's complete case that warned says so in its row", "[sweep]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_sweep_warning";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<SweepAxis> axes = {{"integrator.method", {"euler"}}};  // B1's Euler-210: unstable
  std::vector<SweepCase> cases = make_sweep_cases(b1, {"time.steps=210"}, axes, dir.string());
  run_sweep(cases, 1);
  REQUIRE(cases[0].status == CaseStatus::Complete);
  REQUIRE(!cases[0].result.warnings.empty());
  std::ostringstream table;
  write_sweep_summary(table, dir.string(), axes, cases);
  const test::CsvTable summary = test::read_csv((dir / "summary.csv").string());
  CHECK(summary.rows.at(0).at(2) == "complete");
  CHECK_THAT(summary.rows.at(0).back(), Catch::StartsWith("warning: explicit Euler was unstable"));
  CHECK_THAT(table.str(), Catch::Contains("complete") && Catch::Contains("warning: explicit Euler was unstable"));
  fs::remove_all(dir);
}

TEST_CASE("a sweep's rate-independent case says its imbalance is released in snap-throughs and the steps' error", "[sweep]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_sweep_snap";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<SweepAxis> axes = {{"interface.alpha", {"0", "1"}}};
  std::vector<SweepCase> cases = make_sweep_cases(b1, {}, axes, dir.string());
  run_sweep(cases, 1);
  REQUIRE(cases[0].status == CaseStatus::Complete);
  REQUIRE(cases[1].status == CaseStatus::Complete);
  std::ostringstream table;
  write_sweep_summary(table, dir.string(), axes, cases);
  const test::CsvTable summary = test::read_csv((dir / "summary.csv").string());
  // B1 snaps through at alpha = 0: most of w's work is released in the jumps (README: 0.79),
  // while the viscous case closes its balance to the integrator's accuracy.
  const std::size_t imbalance = summary.header.size() - 4;
  REQUIRE(summary.header.at(imbalance) == "energy imbalance (relative)");
  CHECK(std::stod(summary.rows.at(0).at(imbalance)) > 0.5);
  CHECK(std::stod(summary.rows.at(1).at(imbalance)) < 1e-2);
  CHECK_THAT(summary.rows.at(0).back(), Catch::StartsWith("rate-independent (alpha = 0): the imbalance is the work "
                                                          "released in snap-throughs and the steps' error"));
  CHECK(summary.rows.at(1).back().empty());
  fs::remove_all(dir);
}

TEST_CASE("a sweep whose first case fails: the summary keeps its columns, the failed row has a status and empty cells",
          "[sweep]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_sweep_failed";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // Too few sweeps for the first case's contact solves; the others are fine.
  const std::vector<SweepAxis> axes = {{"solver.max_iterations", {"2", "2000"}}, {"interface.mu", {"0.2", "0.3"}}};
  std::vector<SweepCase> cases =
      make_sweep_cases(b1, {"integrator.method=euler", "solver.active_set=false", "time.T=2.0", "output.times=[1.0]",
                            "loads.[0].value=0.06"},
                       axes, dir.string());
  run_sweep(cases, 1);
  std::ostringstream table;
  write_sweep_summary(table, dir.string(), axes, cases);
  REQUIRE(cases[0].status == CaseStatus::Failed);
  CHECK(cases[3].status == CaseStatus::Complete);
  const test::CsvTable summary = test::read_csv((dir / "summary.csv").string());
  REQUIRE(summary.rows.size() == 4);
  CHECK(summary.header[1] == "solver.max_iterations");
  CHECK(summary.header[2] == "interface.mu");
  CHECK(summary.header[3] == "status");
  for (const auto& row : summary.rows) CHECK(row.size() == summary.header.size());
  CHECK(summary.rows[0][1] == "2");
  CHECK(summary.rows[0][3] == "failed");
  CHECK(summary.rows[0][4].empty());  // no peak force: not a zero that looks like data
  CHECK_THAT(summary.rows[0].back(), Catch::Contains("did not converge"));
  CHECK(summary.rows[3][3] == "complete");
  CHECK(std::stod(summary.rows[3][4]) > 0);
  // The job list reruns each case on its own, quoted for the shell, from any directory: the
  // config, the program given with a directory and the cases' directories made absolute.
  write_sweep_jobs(dir.string(), cases, "rccm", b1);
  std::ifstream jobs(dir / "jobs.txt");
  std::string first;
  std::getline(jobs, first);
  CHECK_THAT(first, Catch::StartsWith("'rccm' run '" + b1 + "' -q") && Catch::Contains("--set 'solver.max_iterations=2'") &&
                        Catch::Contains(" -o '" + (dir / cases[0].name).string() + "'"));
  const fs::path here = fs::current_path();
  fs::current_path(dir);
  write_sweep_jobs(".", cases, "./bin/rccm", "study/b1.cfg");
  fs::current_path(here);
  std::ifstream relative(dir / "jobs.txt");
  std::getline(relative, first);
  CHECK_THAT(first, Catch::StartsWith("'" + (dir / "bin/rccm").string() + "' run '" + (dir / "study/b1.cfg").string() + "' -q") &&
                        Catch::EndsWith(" -o '" + (dir / cases[0].name).string() + "'"));
  fs::remove_all(dir);
}

TEST_CASE("a resumed sweep keeps its complete cases and restarts its stopped one: the uninterrupted sweep's summary",
          "[sweep]") {
  const fs::path whole = fs::temp_directory_path() / "rccm_test_sweep_whole";
  const fs::path parts = fs::temp_directory_path() / "rccm_test_sweep_parts";
  for (const fs::path& d : {whole, parts}) {
    fs::remove_all(d);
    fs::create_directories(d);
  }
  // Fixed steps: a restart takes the same steps, so the same figures to round-off.
  const std::vector<SweepAxis> axes = {{"interface.alpha", {"1", "10", "100"}}};
  const std::vector<std::string> fixed = {"integrator.method=euler", "time.steps=300"};
  std::vector<SweepCase> reference = make_sweep_cases(b1, fixed, axes, whole.string());
  run_sweep(reference, 2);
  std::ostringstream table;
  write_sweep_summary(table, whole.string(), axes, reference);

  // alpha = 1 completes, alpha = 10 is stopped at step 170 (a Ctrl-C), alpha = 100 never starts.
  std::vector<SweepCase> cases = make_sweep_cases(b1, fixed, axes, parts.string());
  std::vector<SweepCase> first(cases.begin(), cases.begin() + 1);
  run_sweep(first, 1);
  RunOptions stopped;
  stopped.write_files = true;
  stopped.observer = [](const AcceptedStep& a) {
    if (a.step == 170) request_stop(SIGINT);
  };
  REQUIRE_THROWS_AS(Simulation(cases[1].config, stopped).run(), Interrupted);
  request_stop(0);
  const std::string kept = test::read_text((parts / "alpha=1" / "history.csv").string());

  // A sweep of other settings into that directory is refused before anything runs.
  std::vector<SweepCase> other = make_sweep_cases(b1, {"integrator.method=euler", "time.steps=301"}, axes, parts.string());
  CHECK_THROWS_WITH(plan_resumed_sweep(other),
                    Catch::Contains("sweep --restart: case alpha=1: ") && Catch::Contains("a run of other settings") &&
                        Catch::Contains("(time.steps differs)"));
  CHECK(test::read_text((parts / "alpha=1" / "history.csv").string()) == kept);

  // Other numerical controls (a restart may change them): the complete case is kept, and said so.
  std::vector<SweepCase> controls =
      make_sweep_cases(b1, {"integrator.method=euler", "time.steps=300", "solver.tolerance=1e-9"}, axes, parts.string());
  CHECK_THAT(plan_resumed_sweep(controls).at(0),
             Catch::StartsWith("alpha=1: complete, kept (it ran with other numerical controls"));
  // A case directory that is a file is refused before anything runs.
  const fs::path odd = fs::temp_directory_path() / "rccm_test_sweep_odd";
  fs::remove_all(odd);
  fs::create_directories(odd);
  std::ofstream(odd / "alpha=1") << "not a directory\n";
  std::vector<SweepCase> in_odd = make_sweep_cases(b1, fixed, axes, odd.string());
  CHECK_THROWS_WITH(plan_resumed_sweep(in_odd), Catch::Contains("case alpha=1: ") && Catch::Contains("is a file, not a directory"));
  fs::remove_all(odd);

  const std::vector<std::string> notes = plan_resumed_sweep(cases);
  CHECK(notes.size() == 2);
  CHECK(notes.at(0) == "alpha=1: complete, kept");
  CHECK(cases[0].start == CaseStart::Kept);
  CHECK(cases[1].start == CaseStart::Restart);
  CHECK(cases[2].start == CaseStart::Fresh);
  run_sweep(cases, 2);
  write_sweep_summary(table, parts.string(), axes, cases);
  CHECK(test::read_text((parts / "alpha=1" / "history.csv").string()) == kept);  // not run again
  // A report.json that says the run did not complete, beside a report.txt that says it did, is
  // no complete case.
  const std::string json = test::read_text((parts / "alpha=1" / "report.json").string());
  std::ofstream((parts / "alpha=1" / "report.json").string())
      << std::regex_replace(json, std::regex("\"complete\": true"), "\"complete\": false");
  std::vector<SweepCase> stale = make_sweep_cases(b1, fixed, axes, parts.string());
  CHECK_THROWS_WITH(plan_resumed_sweep(stale), Catch::Contains("the report of a run that did not complete"));
  std::ofstream((parts / "alpha=1" / "report.json").string()) << json;
  CHECK(cases[1].result.restarted_at > 0);                                        // went on, not afresh
  CHECK(cases[1].result.integrator.steps == reference[1].result.integrator.steps);

  // The summary is the uninterrupted sweep's, figure by figure (the wall times aside).
  const test::CsvTable a = test::read_csv((whole / "summary.csv").string()),
                       b = test::read_csv((parts / "summary.csv").string());
  REQUIRE(a.header == b.header);
  REQUIRE(a.rows.size() == 3);
  REQUIRE(b.rows.size() == 3);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t k = 0; k < a.header.size(); ++k) {
      INFO(a.rows[r][0] << ", " << a.header[k] << ": " << a.rows[r][k] << " against " << b.rows[r][k]);
      if (a.header[k] == "wall [s]") continue;
      char* end = nullptr;
      const double x = std::strtod(a.rows[r][k].c_str(), &end);
      if (a.rows[r][k].empty() || *end != '\0')
        CHECK(a.rows[r][k] == b.rows[r][k]);
      else
        CHECK(std::abs(std::stod(b.rows[r][k]) - x) <= 1e-9 * std::max(1.0, std::abs(x)));
    }
  fs::remove_all(whole);
  fs::remove_all(parts);
}

TEST_CASE("a sweep of a gmsh geometry on two threads reads the meshes first and more viscosity gives a higher peak", "[sweep]") {
  // Two blocks glued along y = 2 (tests/meshes/two_blocks.geo) and pulled apart: run_sweep
  // reads the meshes (rccm-gmsh) before either case computes and hands them over.
  const fs::path dir = fs::temp_directory_path() / "rccm_test_sweep_gmsh";
  fs::remove_all(dir);
  const std::string text = "mesh = { file = \"" RCCM_SOURCE_DIR "/tests/meshes/two_blocks.geo\"; };\n"
                           "material = { E = 1000.0; nu = 0.3; };\n"
                           "interface = { boundary = \"upper_bottom\"; opposite = \"lower_top\"; Cn = 100.0; "
                           "Ct = 100.0; w = 0.01; alpha = 1.0; mu = 0.3; };\n"
                           "loads = ( { node_set = \"top\"; type = \"displacement\"; component = \"y\"; value = 0.05; },\n"
                           "          { node_set = \"bottom\"; type = \"displacement\"; component = \"y\"; value = 0.0; },\n"
                           "          { node_set = \"bottom\"; type = \"displacement\"; component = \"x\"; value = 0.0; } );\n"
                           "time = { T = 1.0; };\n";
  const fs::path cfg = dir / "glued.cfg";
  fs::create_directories(dir);
  std::ofstream(cfg) << text;
  const std::vector<SweepAxis> axes = {{"interface.alpha", {"0.1", "10"}}};
  std::vector<SweepCase> cases = make_sweep_cases(cfg.string(), {}, axes, (dir / "sweep").string());
  run_sweep(cases, 2);
  for (const SweepCase& c : cases) {
    INFO(c.name << ": " << c.error);
    REQUIRE(c.status == CaseStatus::Complete);
    CHECK(!c.mesh);  // handed to its run
  }
  CHECK(cases[0].result.peak_force[0] < cases[1].result.peak_force[0]);
  fs::remove_all(dir);
}
