// Result files: what is written equals what the solver computed, to the printed precision;
// names with commas survive; the initial state, probes, every load's displacement; the JSON
// report at full precision; ParaView frames.
#include "helpers.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/app/stop_request.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/io/run_report.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rccm;
namespace fs = std::filesystem;

namespace {

RunResult run_into(const fs::path& dir, const std::string& config, std::vector<std::string> overrides,
                   bool restart = false, int stop_at_step = -1) {
  overrides.push_back("output.directory=" + dir.string());
  RunOptions options;
  options.write_files = true;
  options.force = !restart;
  options.restart = restart;
  options.observer = [stop_at_step](const AcceptedStep& a) {
    if (a.step == stop_at_step) request_stop(SIGTERM);
  };
  return Simulation(load_config(config, overrides), options).run();
}

std::string interface_file(const fs::path& dir, double t) {
  std::ostringstream name;
  name << "interface_t" << t << ".csv";
  return (dir / name.str()).string();
}

}  // namespace

TEST_CASE("CSV round trip: interface, history and curves hold the solver's values", "[output]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_output";
  const RunResult r = run_into(dir, test::shipped("b1.cfg"), {"integrator.method=euler"});

  // Interface files: one per output time and T, every field of every node.
  REQUIRE(r.snapshots.size() == 3);
  for (const Snapshot& s : r.snapshots) {
    const test::CsvTable t = test::read_csv(interface_file(dir, s.t));
    REQUIRE(t.rows.size() == static_cast<std::size_t>(s.beta.size()));
    const std::vector<double> beta = t.numbers("beta"), un = t.numbers("u_n [mm]"), ut = t.numbers("u_t [mm]"),
                              Rn = t.numbers("Rbar_n [N]"), Rt = t.numbers("Rbar_t [N]");
    for (Eigen::Index i = 0; i < s.beta.size(); ++i) {
      CHECK(beta[i] == Approx(s.beta[i]).epsilon(1e-10).margin(1e-300));
      CHECK(un[i] == Approx(s.u[2 * i + 1]).epsilon(1e-10).margin(1e-300));
      CHECK(ut[i] == Approx(s.u[2 * i]).epsilon(1e-10).margin(1e-300));
      CHECK(Rn[i] == Approx(s.Rbar[2 * i + 1]).epsilon(1e-10).margin(1e-300));
      CHECK(Rt[i] == Approx(s.Rbar[2 * i]).epsilon(1e-10).margin(1e-300));
    }
  }
  // History: a row per accepted step (and the initial state), the watched point B = node 0.
  const test::CsvTable history = test::read_csv((dir / "history.csv").string());
  REQUIRE(history.rows.size() == r.steps.size());
  CHECK(history.numbers("t [s]").back() == Approx(10.0));
  CHECK(history.numbers("B beta").back() == Approx(r.snapshots.back().beta[0]).epsilon(1e-10).margin(1e-300));
  // Curves: the last row carries the run's energy terms and the debonded length of the last snapshot.
  const test::CsvTable curves = test::read_csv((dir / "curves.csv").string());
  REQUIRE(curves.rows.size() == r.steps.size());
  CHECK(curves.numbers("external work [N mm]").back() == Approx(r.energy.external_work).epsilon(1e-10));
  CHECK(curves.numbers("L0 top_left.y value [mm]").back() == Approx(0.3).epsilon(1e-12));
  CHECK(curves.numbers("debonded length [mm]").back() == Approx(r.snapshots.back().debonded_length).epsilon(1e-12));
  // The report exists in both forms; the JSON holds the energy terms to the last bit.
  CHECK(fs::file_size(dir / "report.txt") > 0);
  std::ifstream json(dir / "report.json");
  const nlohmann::json report = nlohmann::json::parse(json);
  CHECK(report["energy"]["damage_dissipation"].get<double>() == r.energy.damage_dissipation);
  CHECK(report["energy"]["imbalance"].get<double>() == r.energy.imbalance());
  CHECK(report["per_step"].size() == r.steps.size());
  CHECK(report["complete"].get<bool>());
  // W0 of B1's 33 pairs: dense, 66^2 doubles.
  CHECK(report["flexibility"].get<std::string>() == "dense, 66 x 66 (0.0348 MB)");
  CHECK(test::read_text((dir / "report.txt").string()).find("interface flexibility W0: dense, 66 x 66 (0.0348 MB)\n") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a watch name with a comma and a quote: quoted in the CSV header, and a restart keeps every line",
          "[output][restart]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_output_quoted";
  const std::vector<std::string> settings = {
      "integrator.method=euler", "time.steps=300", "output.checkpoint_steps=50",
      "output.watch=({name=\"B, under \\\"A\\\"\";point=[0.0,0.0];})"};
  request_stop(0);
  REQUIRE_THROWS_AS(run_into(dir, test::shipped("b1.cfg"), settings, false, 120), Interrupted);
  request_stop(0);
  const RunResult r = run_into(dir, test::shipped("b1.cfg"), settings, true);
  const test::CsvTable history = test::read_csv((dir / "history.csv").string());
  CHECK(history.header[12] == "B, under \"A\" beta");
  CHECK(history.rows.size() == r.steps.size());
  CHECK(history.rows.size() == 303);  // the initial state, 300 steps and the 2 output times, each once
  for (const auto& row : history.rows) CHECK(row.size() == history.header.size());
  fs::remove_all(dir);
}

TEST_CASE("the initial state at output time 0, probes in the body, every load's displacement in curves.csv",
          "[output]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_output_probes";
  // A block pulled by a force on its top-right corner (force control): the load's displacement
  // column is the corner's displacement, which a probe there sees too.
  const std::string text = R"(
mesh = { size = [10.0, 5.0]; nx = 8; ny = 4; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.3; };
loads = ( { node_set = "top_right"; type = "force"; component = "y"; value = 2.0; },
          { node_set = "left"; type = "displacement"; component = "x"; value = 0.0; } );
time = { T = 1.0; steps = 10; };
integrator = { method = "euler"; };
output = { times = [0.0, 0.5]; probes = ( { name = "corner"; point = [10.0, 5.0]; }, { name = "middle"; point = [5.0, 2.6]; } ); };
)";
  const std::string path = test::write_temp_config(text);
  const RunResult r = run_into(dir, path, {});
  std::remove(path.c_str());
  // Output time 0: the initial state, beta0 and no force.
  REQUIRE(r.snapshots.size() == 3);
  CHECK(r.snapshots[0].t == 0.0);
  const test::CsvTable t0 = test::read_csv(interface_file(dir, 0.0));
  for (double b : t0.numbers("beta")) CHECK(b == 1.0);
  for (double R : t0.numbers("Rbar_n [N]")) CHECK(R == 0.0);
  const test::CsvTable curves = test::read_csv((dir / "curves.csv").string());
  const test::CsvTable history = test::read_csv((dir / "history.csv").string());
  const std::vector<double> load_u = curves.numbers("L0 top_right.y displacement [mm]"),
                            probe_u = history.numbers("corner u_y [mm]"), F = curves.numbers("L0 top_right.y force [N]");
  REQUIRE(load_u.size() == probe_u.size());
  for (std::size_t k = 0; k < load_u.size(); ++k) CHECK(load_u[k] == Approx(probe_u[k]).epsilon(1e-12).margin(1e-300));
  CHECK(load_u.back() > 0);                          // pulled up, the corner rises
  CHECK(F.back() == Approx(2.0).epsilon(1e-9));      // the resultant of a force load is the force
  CHECK(history.numbers("middle u_x [mm]").size() == load_u.size());
  // The displacement load's column is the prescribed value.
  for (double u : curves.numbers("L1 left.x displacement [mm]")) CHECK(u == 0.0);
  fs::remove_all(dir);
}

TEST_CASE("ParaView frames at t = 0, at the output times and every output.every steps", "[output]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_output_frames";
  run_into(dir, test::shipped("b1.cfg"), {"integrator.method=euler", "output.every=50"});
  std::ifstream pvd(dir / "results.pvd"), ipvd(dir / "interface.pvd");
  const std::string bodies((std::istreambuf_iterator<char>(pvd)), {}), interface((std::istreambuf_iterator<char>(ipvd)), {});
  // t = 0, steps 50, 100, 150, 200 (every 50 of 212), the two output times and T.
  const auto frames = [](const std::string& s) {
    std::size_t n = 0;
    for (std::size_t k = s.find("<DataSet"); k != std::string::npos; k = s.find("<DataSet", k + 1)) ++n;
    return n;
  };
  CHECK(frames(bodies) == 8);
  CHECK(frames(interface) == 8);
  CHECK(bodies.find("timestep=\"0\" file=\"mesh_0000.vtu\"") != std::string::npos);
  for (int k = 0; k < 8; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "interface_%04d.vtp", k);
    CHECK(fs::exists(dir / name));
  }
  fs::remove_all(dir);
}

TEST_CASE("a frame at every step solves the body once per accepted state: the bench's body-solve timing counts them",
          "[output]") {
  // The full displacement is solved once per accepted state that needs it (step 0, each frame)
  // and reused by the strain check and the output times at the same state.
  const fs::path dir = fs::temp_directory_path() / "rccm_test_output_body_solves";
  const RunResult r = run_into(dir, test::shipped("b1.cfg"), {"integrator.method=euler", "output.every=1"});
  CHECK(r.body_solves == r.integrator.steps + 1);
  CHECK(r.body_solve_seconds > 0);
  CHECK(r.body_solve_seconds < r.wall_seconds);
  std::ifstream json(dir / "report.json");
  const nlohmann::json report = nlohmann::json::parse(json);
  CHECK(report["body_solves"].get<long>() == r.integrator.steps + 1);
  CHECK(r.strain_checks == r.integrator.steps + 1);  // each state's body solved anyway: checked at every step
  CHECK(report["strain_checks"].get<long>() == r.strain_checks);
  CHECK(report["strain_checks_left_out"].get<long>() == 0);
  CHECK(report["contact_solve_seconds"].get<double>() == r.solves.seconds);
  CHECK(r.solves.seconds + r.body_solve_seconds + r.setup_seconds < r.wall_seconds);
  fs::remove_all(dir);
}

TEST_CASE("the rate-independent limit names the energy its snap-through releases with the steps' error", "[output]") {
  const fs::path dir = fs::temp_directory_path() / "rccm_test_output_released";
  run_into(dir, test::shipped("b1.cfg"), {"interface.alpha=0"});
  std::ifstream txt(dir / "report.txt"), json(dir / "report.json");
  const std::string text((std::istreambuf_iterator<char>(txt)), {});
  CHECK_THAT(text, Catch::Contains("integrator: rate-independent") && Catch::Contains("snap-through and step error") &&
                       !Catch::Contains("  imbalance") && !Catch::Contains("It is negative here"));
  const nlohmann::json report = nlohmann::json::parse(json);
  CHECK(report["energy"].contains("snap_through_and_step_error"));
  CHECK(report["energy"]["relative_error"].get<double>() > 0.5);  // B1 unzips in a jump: README 0.79
  CHECK(!report["energy"].contains("imbalance"));
  fs::remove_all(dir);
}

TEST_CASE("the rate-independent balance: a stable path leaves only the steps' error and a snap-through does not shrink",
          "[output]") {
  // A bonded block pulled off uniformly, alpha = 0: stable since E > 3 H Cn (the opening d =
  // u + H w^2 / (E Cn u^3) grows with u), so nothing snaps and beta = w / (Cn u^2) past the
  // critical opening sqrt(w / Cn): what the balance leaves is the trapezoid rule's error, dt^2.
  const std::string block = test::write_temp_config(R"(
mesh = { size = [10.0, 1.0]; nx = 5; ny = 2; };
material = { E = 1000.0; nu = 0.0; };
interface = { boundary = "bottom"; Cn = 100.0; Ct = 100.0; w = 0.01; alpha = 0.0; mu = 0.3; };
loads = ( { node_set = "top"; type = "displacement"; component = "y"; value = 0.04; } );
time = { T = 1.0; };
)");
  const auto left = [&](const std::string& file, int steps) {
    const RunResult r = Simulation(load_config(file, {"time.steps=" + std::to_string(steps), "interface.alpha=0"}), {}).run();
    return std::copysign(r.energy.relative_error(), r.energy.imbalance());  // of the largest term
  };
  const double e200 = left(block, 200), e400 = left(block, 400), e800 = left(block, 800);
  INFO("left by the balance, relative: " << e200 << " " << e400 << " " << e800);
  CHECK(e200 / e400 == Approx(4.0).epsilon(0.05));
  CHECK(e400 / e800 == Approx(4.0).epsilon(0.05));
  CHECK(std::abs(e800) < 2e-5);
  // At 100 steps the kink at the critical opening leaves it negative: no snap-through takes work
  // in, and the report says it is the steps' error.
  const fs::path dir = fs::temp_directory_path() / "rccm_test_output_stable_rate_independent";
  const RunResult r = run_into(dir, block, {"time.steps=100"});
  CHECK(r.energy.imbalance() < -1e-6);
  CHECK_THAT(test::read_text((dir / "report.txt").string()),
             Catch::Contains("It is negative here: no snap-through releases negative work, so the steps' error is at"));
  fs::remove_all(dir);
  // B1 unzips in a jump: most of w's work is released there, with twice the steps as well.
  const double b210 = left(test::shipped("b1.cfg"), 210), b420 = left(test::shipped("b1.cfg"), 420);
  CHECK(b210 > 0.5);
  CHECK(b420 > 0.5);
}

TEST_CASE("The closing lines say how many of the compressed W0's sweeps several threads shared", "[output]") {
  SolveCounts counts;
  ContactSolution s;
  s.iterations = 7;
  s.timed_sweeps = 6;
  s.threaded_sweeps = 4;
  counts.add(s, 0.0);
  counts.add(s, 0.0);
  CHECK(counts.timed_sweeps == 12);
  CHECK(counts.threaded_sweeps == 8);
  CHECK(threaded_sweeps_line(counts, 2).rfind("sweeps in 2 threads: 8 of the compressed W0's 12 ", 0) == 0);
  CHECK(threaded_sweeps_line(counts, 1).empty());    // one thread to take: nothing to say
  CHECK(threaded_sweeps_line(SolveCounts{}, 2).empty());  // a dense W0: no sweep timed
}
