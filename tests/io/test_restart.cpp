// Interrupted runs and restart (README "Interrupted runs and restart"): a run stopped by a
// signal writes a checkpoint; `--restart` from it gives what the uninterrupted run gives.
#include "helpers.hpp"
#include "rccm/io/checkpoint.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/app/stop_request.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <functional>
#include <limits>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace rccm;
namespace fs = std::filesystem;

namespace {

/// `text` with CRLF line ends, as a copy through another system leaves it.
std::string crlf(const std::string& text) {
  std::string out;
  for (char ch : text) out += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
  return out;
}

/// The file at `path` turned to CRLF line ends.
void to_crlf(const std::string& path) {
  const std::string text = crlf(test::read_text(path));  // read before the stream truncates the file
  std::ofstream(path, std::ios::binary) << text;
}

Config b1(const std::string& directory, std::vector<std::string> overrides) {
  overrides.push_back("output.directory=\"" + directory + "\"");
  overrides.push_back("output.checkpoint_steps=40");
  return load_config(RCCM_SOURCE_DIR "/config/b1.cfg", overrides);
}

RunResult run(const Config& cfg, bool restart = false, int stop_at_step = -1) {
  RunOptions o;
  o.write_files = true;
  o.force = !restart;
  o.restart = restart;
  o.observer = [stop_at_step](const AcceptedStep& a) {
    if (a.step == stop_at_step) request_stop(SIGTERM);
  };
  return Simulation(cfg, o).run();
}

/// B1 in 100 explicit Euler steps (`euler`), stopped by SIGTERM at step 50 in `dir`: its
/// files and checkpoint to take up.
const std::vector<std::string> euler{"integrator.method=\"euler\"", "time.steps=100"};
void stop_euler_halfway(const std::string& dir) {
  request_stop(0);
  REQUIRE_THROWS_AS(run(b1(dir, euler), false, 50), Interrupted);
  request_stop(0);
}

std::size_t lines(const std::string& path) {
  std::ifstream in(path);
  std::size_t n = 0;
  for (std::string l; std::getline(in, l);) ++n;
  return n;
}

}  // namespace

TEST_CASE("a run stopped by SIGTERM and restarted from its checkpoint gives the uninterrupted results", "[restart]") {
  struct Case {
    std::vector<std::string> settings;
    int stop_at;
    double tolerance;  // on beta, Rbar, u relative to their largest value
  };
  // Fixed steps: the same steps, so the same results to the contact solver's round-off.
  // ARKODE: restarted with its last step size, it takes its own steps after the checkpoint,
  // so the results agree to its global error (rtol 1e-8: ~4e-6 in beta at the front node).
  // With K0's springs following beta, the restart condenses with the checkpoint's springs.
  const Case cases[] = {{{"integrator.method=\"euler\"", "time.steps=300"}, 170, 1e-9},
                        {{"integrator.method=\"euler\"", "time.steps=300", "solver.springs_follow_beta=true"}, 170, 1e-9},
                        {{"integrator.rtol=1e-8", "time.T=6.0"}, 400, 1e-5}};
  for (const Case& c : cases) {
    const std::string whole = fs::temp_directory_path() / "rccm_restart_whole";
    const std::string parts = fs::temp_directory_path() / "rccm_restart_parts";
    const RunResult reference = run(b1(whole, c.settings));

    request_stop(0);
    REQUIRE_THROWS_AS(run(b1(parts, c.settings), false, c.stop_at), Interrupted);
    request_stop(0);
    const Checkpoint ck = read_checkpoint(parts, b1(parts, c.settings));
    CHECK(ck.step == c.stop_at);
    const bool follow = c.settings.back() == "solver.springs_follow_beta=true";
    CHECK((ck.springs_beta.minCoeff() < 1) == follow);  // condensed anew before the stop
    // The stopped run's report counts the steps its files hold: history.csv's rows after t = 0.
    CHECK_THAT(test::read_text(parts + "/report.txt"), Catch::Contains("accepted steps          " + std::to_string(c.stop_at) + " ("));
    CHECK(lines(parts + "/history.csv") == std::size_t(c.stop_at) + 2);
    CHECK(ck.state.t < 10.0);
    const RunResult restarted = run(b1(parts, c.settings), true);
    // The times beside the wall time are this process's: the solves since the restart.
    CHECK(restarted.solves_before_restart.contact_solves == ck.progress.solves.contact_solves);
    CHECK(restarted.solves_before_restart.seconds == ck.progress.solves.seconds);
    const SolveCounts own = solves_of_this_process(restarted);
    CHECK(own.contact_solves == restarted.solves.contact_solves - ck.progress.solves.contact_solves);
    CHECK(own.contact_solves > 0);
    CHECK(own.seconds <= restarted.wall_seconds);
    CHECK(reference.solves_before_restart.contact_solves == 0);

    REQUIRE(restarted.snapshots.size() == reference.snapshots.size());
    for (std::size_t k = 0; k < reference.snapshots.size(); ++k) {
      const Snapshot &a = reference.snapshots[k], &b = restarted.snapshots[k];
      CHECK(a.t == b.t);
      CHECK((a.beta - b.beta).cwiseAbs().maxCoeff() <= c.tolerance);
      CHECK((a.Rbar - b.Rbar).cwiseAbs().maxCoeff() <= c.tolerance * a.Rbar.cwiseAbs().maxCoeff());
      CHECK((a.u - b.u).cwiseAbs().maxCoeff() <= c.tolerance * a.u.cwiseAbs().maxCoeff());
    }
    // The energy terms are step sums (trapezoid rule): they agree to the run's own imbalance.
    const double scale = reference.energy.external_work;
    const double energy_tolerance = std::max(c.tolerance, reference.energy.relative_error());
    CHECK(std::abs(restarted.energy.external_work - scale) <= energy_tolerance * scale);
    CHECK(std::abs(restarted.energy.damage_dissipation - reference.energy.damage_dissipation) <= energy_tolerance * scale);
    CHECK(std::abs(restarted.peak_force[0] - reference.peak_force[0]) <= c.tolerance * std::abs(reference.peak_force[0]));
    // The balance's round-off floor (sqrt(eps) w |Gamma_c|) is the model's, not the checkpoint's.
    CHECK(reference.energy.round_off > 0);
    CHECK(restarted.energy.round_off == reference.energy.round_off);
    // The files hold each accepted step once: what the stopped run wrote after its
    // checkpoint was replaced, not repeated.
    CHECK(restarted.steps.size() == static_cast<std::size_t>(restarted.integrator.steps + 1));
    CHECK(lines(parts + "/history.csv") == restarted.steps.size() + 1);
    CHECK(lines(parts + "/curves.csv") == restarted.steps.size() + 1);
    if (c.tolerance < 1e-8) {
      CHECK(restarted.integrator.steps == reference.integrator.steps);
      CHECK(lines(parts + "/history.csv") == lines(whole + "/history.csv"));
    }
    // ParaView's collections list the uninterrupted run's frames (t = 0, three output times
    // and T), each file there: the restart keeps the frames before its checkpoint.
    for (const char* pvd : {"/results.pvd", "/interface.pvd"}) {
      INFO(pvd);
      const std::string frames = test::read_text(parts + pvd);
      CHECK(frames == test::read_text(whole + pvd));
      CHECK(std::count(frames.begin(), frames.end(), '\n') > 4);
    }
    for (const char* frame : {"0000", "0001", "0002", "0003"})
      CHECK((fs::exists(parts + "/mesh_" + frame + ".vtu") && fs::exists(parts + "/interface_" + frame + ".vtp")));
    CHECK(!fs::exists(parts + "/mesh_" + std::string("0004.vtu")));
    CHECK_THAT(test::read_text(parts + "/report.txt"), Catch::Contains(" s) since the restart at t = "));
    CHECK(restarted.restarted_at == ck.state.t);
    CHECK(reference.restarted_at == -1);
    // A restart of the finished run is refused, its files untouched.
    const std::string report = test::read_text(parts + "/report.txt");
    CHECK_THROWS_WITH(run(b1(parts, c.settings), true), Catch::Contains("checkpoint.txt: the run reached time.T = ") && Catch::Contains(" s: there is nothing to go on with"));
    CHECK(test::read_text(parts + "/report.txt") == report);
    CHECK(fs::exists(parts + "/mesh_0003.vtu"));
    // So is it after a copy through another system (CRLF line ends in the report and the checkpoint;
    // a guard: the report's status is matched by its prefix, the checkpoint's reader drops the CR).
    for (const char* name : {"/report.txt", "/checkpoint.txt"}) to_crlf(parts + name);
    CHECK_THROWS_WITH(run(b1(parts, c.settings), true), Catch::Contains(" s: there is nothing to go on with"));
    CHECK(fs::exists(parts + "/mesh_0003.vtu"));
    // A run cut off after its checkpoint at T, before its report (kill -9): the restart ends it.
    fs::remove(parts + "/report.txt");
    fs::remove(parts + "/report.json");
    CHECK(run(b1(parts, c.settings), true).snapshots.size() == reference.snapshots.size());
    CHECK_THAT(test::read_text(parts + "/report.txt"), Catch::Contains("status: complete"));
    fs::remove_all(whole);
    fs::remove_all(parts);
  }
}

TEST_CASE("a stop asked while the run records its step 0 ends it at step 1 with its report and checkpoint", "[restart]") {
  const std::string dir = fs::temp_directory_path() / "rccm_stop_at_0";
  request_stop(0);
  CHECK_THROWS_AS(run(b1(dir, {"integrator.method=\"euler\"", "time.steps=300"}), false, 0), Interrupted);
  request_stop(0);
  CHECK_THAT(test::read_text(dir + "/report.txt"), Catch::Contains("status: STOPPED"));
  CHECK(read_checkpoint(dir, b1(dir, {"integrator.method=\"euler\"", "time.steps=300"})).step == 1);
  fs::remove_all(dir);
}

TEST_CASE("a restart from a checkpoint whose pairs are other mesh nodes is refused, the files untouched", "[restart]") {
  // A checkpoint written by a version of rccm that listed the pairs in another order would
  // give each pair another's beta: its contact nodes are checked against the model's.
  const std::string dir = fs::temp_directory_path() / "rccm_restart_reordered";
  stop_euler_halfway(dir);
  Checkpoint ck = read_checkpoint(dir, b1(dir, euler));
  REQUIRE(ck.contact_nodes.size() == std::size_t(ck.state.beta.size()));
  std::swap(ck.contact_nodes[3], ck.contact_nodes[4]);
  write_checkpoint(dir, ck);
  const std::size_t history = lines(dir + "/history.csv");
  CHECK_THROWS_WITH(run(b1(dir, euler), true), Catch::Contains("checkpoint.txt: its contact node 3 is mesh node") &&
                                                   Catch::Contains("start the run afresh with --force"));
  CHECK(lines(dir + "/history.csv") == history);
  std::swap(ck.contact_nodes[3], ck.contact_nodes[4]);  // as written: the restart goes on
  write_checkpoint(dir, ck);
  CHECK(run(b1(dir, euler), true).snapshots.back().t == 10.0);
  fs::remove_all(dir);
}

TEST_CASE("a restart whose CSV lost the rows up to the checkpoint is refused, both CSVs untouched", "[restart]") {
  // The checkpoint survived, the end of curves.csv did not (a power cut, a copy cut short):
  // a restart would leave a gap in time that no later step fills.
  const std::string dir = fs::temp_directory_path() / "rccm_restart_short_csv";
  stop_euler_halfway(dir);
  std::vector<std::string> rows;
  {
    std::ifstream in(dir + "/curves.csv");
    for (std::string l; std::getline(in, l);) rows.push_back(l);
  }
  REQUIRE(rows.size() > 30);
  {
    std::ofstream out(dir + "/curves.csv");  // the first 20 steps only
    for (std::size_t k = 0; k < 21; ++k) out << rows[k] << "\n";
  }
  {  // and a row after the checkpoint in history.csv (its last row, at t = 99), which taking it up would drop
    std::vector<std::string> history_rows;
    std::ifstream in(dir + "/history.csv");
    for (std::string l; std::getline(in, l);) history_rows.push_back(l);
    std::ofstream out(dir + "/history.csv", std::ios::app);
    out << "99" << history_rows.back().substr(history_rows.back().find(',')) << "\n";
  }
  const std::size_t history = lines(dir + "/history.csv");
  CHECK_THROWS_WITH(run(b1(dir, euler), true),
                    Catch::Contains("curves.csv: its rows end at t = ") && Catch::Contains("before the checkpoint's t = ") &&
                        Catch::Contains("run afresh with --force"));
  CHECK(lines(dir + "/history.csv") == history);  // refused before either file was cut at the checkpoint
  CHECK(lines(dir + "/curves.csv") == 21);
  fs::remove_all(dir);
}

TEST_CASE("a restart takes up CSVs with CRLF line ends and leaves them with LF alone", "[restart]") {
  const std::string dir = fs::temp_directory_path() / "rccm_restart_crlf";
  stop_euler_halfway(dir);
  for (const char* name : {"/history.csv", "/curves.csv"}) to_crlf(dir + name);  // copied through another system
  const RunResult r = run(b1(dir, euler), true);
  for (const char* name : {"/history.csv", "/curves.csv"}) {
    INFO(name);
    const std::string text = test::read_text(dir + name);
    CHECK(text.find('\r') == std::string::npos);
    CHECK(lines(dir + name) == r.steps.size() + 1);  // every step once: the header and a row per step
  }
  fs::remove_all(dir);
}

TEST_CASE("a restart drops the interface files of output times after its checkpoint and no file of the user's", "[restart]") {
  // A restart removes interface_t<time>.csv of the times after its checkpoint (written by a run
  // stopped later than its last checkpoint: kill -9), and only those: a user's files whose
  // names start the same (interface_threshold.vtp), and folders, stay.
  const std::string dir = fs::temp_directory_path() / "rccm_restart_user_files";
  fs::remove_all(dir);
  stop_euler_halfway(dir);
  REQUIRE(read_checkpoint(dir, b1(dir, euler)).state.t < 7.0);
  const std::vector<std::string> mine = {"interface_threshold.vtp", "interface_tractions.xlsx", "interface_t0.36.csv.bak",
                                         "interface_thickness.csv", "interface_t7.csv.old", "interface_tests/notes.txt"};
  for (const std::string& name : mine) {
    fs::create_directories(fs::path(dir + "/" + name).parent_path());
    std::ofstream(dir + "/" + name) << "mine\n";
  }
  // A folder bearing the name of a file rccm writes (an output time's, the next frame's) is
  // refused before the restart writes anything (the restart failed on it with an internal
  // error, or would have at the end).
  for (const char* folder : {"interface_t7.5.csv", "mesh_0099.vtu"}) {
    INFO(folder);
    fs::create_directories(dir + "/" + folder + "/sub");
    const std::string history = test::read_text(dir + "/history.csv");
    CHECK_THROWS_WITH(run(b1(dir, euler), true),
                      Catch::Contains(std::string(folder) + "' is not a file but has the name of one rccm writes there"));
    CHECK(test::read_text(dir + "/history.csv") == history);
    fs::remove_all(dir + "/" + folder);
  }
  std::ofstream(dir + "/interface_t7.csv") << "t = 7 s, after the checkpoint\n";
  std::ofstream(dir + "/interface_t1e-05.csv") << "t = 1e-5 s, an output time of another run\n";
  CHECK(run(b1(dir, euler), true).snapshots.back().t == 10.0);
  for (const std::string& name : mine) {
    INFO(name);
    CHECK(fs::is_regular_file(dir + "/" + name));
    if (fs::is_regular_file(dir + "/" + name)) CHECK(test::read_text(dir + "/" + name) == "mine\n");
  }
  CHECK_FALSE(fs::exists(dir + "/interface_t7.csv"));
  CHECK_FALSE(fs::exists(dir + "/interface_t1e-05.csv"));
  for (const char* kept : {"/interface_t3.571.csv", "/interface_t5.143.csv", "/interface_t10.csv"})
    CHECK(fs::exists(dir + kept));
  fs::remove_all(dir);
}

TEST_CASE("a checkpoint reads back bit for bit", "[restart]") {
  const std::string dir = fs::temp_directory_path() / "rccm_checkpoint_bits";
  fs::create_directories(dir);
  const Config cfg = b1(dir, {});
  Checkpoint c;
  c.settings = cfg.settings;
  c.step = 123;
  c.last_step = 1.0 / 3.0;
  c.state.t = 2.0 / 7.0;  // a snapshot's time is at most t
  c.state.beta = Eigen::VectorXd::Random(5).cwiseAbs();
  c.state.beta[0] = 4.9406564584124654e-324;  // the smallest subnormal
  c.state.Rbar = Eigen::VectorXd::Random(10) * 1e-300;
  c.state.u = Eigen::VectorXd::Random(10) * 1e300;  // finite, however large
  c.state.y = Eigen::VectorXd::Random(10);
  c.state.status = {Status::Stick, Status::Slide, Status::Separated, Status::Stick, Status::Slide};
  c.energy = {1.0 / 3, 2.0 / 3, -1e-17, 3.5, 0.1, -0.0};
  c.diagnostics = {44.95, 7};
  c.excursion = {0.25, 0.6, 2};
  c.notes = {{"t = 0.1 s: a note, with: punctuation 'and' (quotes)", "another"}, true, 0.125};
  c.contact_nodes = {7, 3, 100000, 0, 5};
  c.springs_beta = (c.state.beta + Eigen::VectorXd::Constant(5, 1.0 / 3)).cwiseMin(1.0);
  c.progress.peak_force = {203.51};
  c.progress.peak_time = {0.3};
  c.progress.solves = {35443, 87000, 7, 1.25};
  c.progress.integrator = {1616, 616, 35443, 30000};
  c.progress.snapshots = {{0.25, c.state.beta, c.state.Rbar, c.state.u, 11.7}};
  write_checkpoint(dir, c);

  const Checkpoint r = read_checkpoint(dir, cfg);
  CHECK(r.step == c.step);
  CHECK(r.last_step == c.last_step);
  CHECK(r.state.t == c.state.t);
  CHECK(r.state.beta == c.state.beta);
  CHECK(r.state.Rbar == c.state.Rbar);
  CHECK(r.state.u == c.state.u);
  CHECK(r.state.y == c.state.y);
  CHECK(r.state.status == c.state.status);
  CHECK(r.energy.external_work == c.energy.external_work);
  CHECK(r.energy.free_energy_change == c.energy.free_energy_change);
  CHECK(std::signbit(r.energy.normal_contact_work));
  CHECK(r.diagnostics == c.diagnostics);
  CHECK(r.excursion.size == 0.25);
  CHECK(r.excursion.node == 2);
  CHECK(r.contact_nodes == c.contact_nodes);
  CHECK(r.springs_beta == c.springs_beta);
  CHECK(r.notes.said == c.notes.said);
  CHECK(r.notes.deformation_noted);
  CHECK(r.notes.deformation_checked == 0.125);
  CHECK(r.progress.peak_force == c.progress.peak_force);
  CHECK(r.progress.solves.sweeps == c.progress.solves.sweeps);
  CHECK(r.progress.integrator.rejected == c.progress.integrator.rejected);
  REQUIRE(r.progress.snapshots.size() == 1);
  CHECK(r.progress.snapshots[0].u == c.state.u);
  CHECK(r.progress.snapshots[0].debonded_length == 11.7);
  CHECK_FALSE(fs::exists(checkpoint_path(dir) + ".tmp"));
  // The same file with CRLF line ends (copied through another system) reads back the same.
  to_crlf(checkpoint_path(dir));
  const Checkpoint w = read_checkpoint(dir, cfg);
  CHECK(w.state.beta == c.state.beta);
  CHECK(w.state.u == c.state.u);
  CHECK(w.diagnostics == c.diagnostics);
  fs::remove_all(dir);
}

TEST_CASE("a missing, damaged or foreign checkpoint is refused, naming the file", "[restart]") {
  const std::string dir = fs::temp_directory_path() / "rccm_checkpoint_refused";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Config cfg = b1(dir, {});
  const auto message = [&](const Config& c) {
    try {
      read_checkpoint(dir, c);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(message(cfg), Catch::Contains("checkpoint.txt: no checkpoint to restart from"));

  Checkpoint c;
  c.settings = cfg.settings;
  c.settings_parts = cfg.settings_parts;
  c.state.beta = Eigen::VectorXd::Ones(2);
  c.state.Rbar = c.state.u = c.state.y = Eigen::VectorXd::Zero(4);
  c.state.status.assign(2, Status::Separated);
  c.contact_nodes = {0, 1};
  c.springs_beta = Eigen::VectorXd::Ones(2);
  c.progress.peak_force = c.progress.peak_time = {0.0};
  write_checkpoint(dir, c);
  CHECK(message(cfg) == "no error");
  // Another alpha is another run, named; the output directory and checkpoint interval are not.
  CHECK_THAT(message(b1(dir, {"interface.alpha=2.0"})),
             Catch::Contains("written by a run of other settings than ") && Catch::Contains("--set options: interface.alpha differs ("));
  CHECK(message(b1(dir, {"output.checkpoint_steps=7"})) == "no error");

  // A checkpoint cut short (a full disk when it was copied): the line that is wrong is named.
  std::string text;
  {
    std::ifstream in(checkpoint_path(dir));
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(checkpoint_path(dir)) << text.substr(0, text.find("\nu "));
  CHECK_THAT(message(cfg), Catch::Contains("checkpoint.txt:8: expected 'u', found the end of the file"));
  std::ofstream(checkpoint_path(dir)) << text.substr(0, text.find("\nRbar ")) << "\nRbar 4 0x0p+0 1.5 zero";
  CHECK_THAT(message(cfg), Catch::Contains("checkpoint.txt:7: expected a number for 'Rbar', found 'zero'"));
  // A checkpoint of an earlier version (format 2: no contact_nodes) is not called damaged.
  std::ofstream(checkpoint_path(dir)) << "rccm-checkpoint-2" << text.substr(text.find('\n'));
  CHECK_THAT(message(cfg), Catch::Contains("checkpoint.txt: written by another version of rccm (format rccm-checkpoint-2, "
                                           "this version reads rccm-checkpoint-7)"));
  // Format 6 (the settings' hash without the digests) is read: a restart of it goes on, one of
  // other settings is refused without naming them.
  std::ofstream(checkpoint_path(dir)) << "rccm-checkpoint-6\nsettings " << cfg.settings
                                      << text.substr(text.find('\n', text.find("\nsettings ") + 1));
  CHECK(message(cfg) == "no error");
  const std::string refused = message(b1(dir, {"interface.alpha=2.0"}));
  CHECK_THAT(refused, Catch::Contains("written by a run of other settings"));
  CHECK_THAT(refused, !Catch::Contains("differs"));
  fs::remove_all(dir);
}

TEST_CASE("a checkpoint whose state breaks the model's rules is refused, naming the line", "[restart]") {
  const std::string dir = fs::temp_directory_path() / "rccm_checkpoint_values";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Config cfg = b1(dir, {});
  Checkpoint good;
  good.settings = cfg.settings;
  good.state.t = 1.0;
  good.state.beta = Eigen::VectorXd::Constant(3, 0.5);
  good.state.Rbar = good.state.u = good.state.y = Eigen::VectorXd::Zero(6);
  good.state.status.assign(3, Status::Separated);
  good.contact_nodes = {4, 5, 6};
  good.springs_beta = Eigen::Vector3d(1.0, 0.5, 0.75);
  good.progress.peak_force = {1.0};
  good.progress.peak_time = {0.5};
  const auto message = [&](const std::function<void(Checkpoint&)>& damage) {
    Checkpoint c = good;
    damage(c);
    write_checkpoint(dir, c);
    try {
      read_checkpoint(dir, cfg);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  CHECK(message([](Checkpoint&) {}) == "accepted");
  CHECK_THAT(message([&](Checkpoint& c) { c.state.beta[1] = nan; }), Catch::Contains(":6: beta must be in [0, 1]"));
  CHECK_THAT(message([](Checkpoint& c) { c.state.beta[1] = 2.0; }), Catch::Contains(":6: beta must be in [0, 1]"));
  CHECK_THAT(message([](Checkpoint& c) { c.state.t = 11.0; }), Catch::Contains(":5: t must be in [0, time.T"));
  CHECK_THAT(message([](Checkpoint& c) { c.state.t = -1.0; }), Catch::Contains(":5: t must be in [0, time.T"));
  CHECK_THAT(message([&](Checkpoint& c) { c.energy.external_work = inf; }), Catch::Contains(":12: energy must be 6 finite"));
  CHECK_THAT(message([&](Checkpoint& c) { c.state.u[0] = nan; }), Catch::Contains(":8: u must be finite"));
  CHECK_THAT(message([](Checkpoint& c) { c.state.y = Eigen::VectorXd::Zero(5); }),
             Catch::Contains(":9: y must have 2 or 3 components per contact node"));
  // K0's springs were set at an earlier beta (Model::condense), which only falls.
  for (const double s : {0.4, 1.5, nan})
    CHECK_THAT(message([&](Checkpoint& c) { c.springs_beta[1] = s; }), Catch::Contains(":11: springs_beta must be in [beta, 1]"));
  CHECK_THAT(message([](Checkpoint& c) { c.springs_beta = Eigen::VectorXd::Ones(2); }),
             Catch::Contains(":11: springs_beta must be in [beta, 1], one per contact node"));
  CHECK_THAT(message([](Checkpoint& c) { c.step = -3; }), Catch::Contains(":3: step must be a whole number"));
  CHECK_THAT(message([](Checkpoint& c) { c.progress.snapshots = {{5.0, c.state.beta, c.state.Rbar, c.state.u, 0.0}}; }),
             Catch::Contains("a snapshot's time must be in [0, t]"));
  CHECK_THAT(message([](Checkpoint& c) { c.contact_nodes = {4, 5}; }),
             Catch::Contains("contact_nodes must be one mesh node per contact node"));
  CHECK_THAT(message([](Checkpoint& c) { c.contact_nodes = {4, -5, 6}; }),
             Catch::Contains("contact_nodes must be one mesh node per contact node"));
  // Values no int holds (written by hand: the writer takes ints).
  std::string text;
  {
    write_checkpoint(dir, good);
    std::ifstream in(checkpoint_path(dir));
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  for (const char* nodes : {"contact_nodes 3 4 inf 6", "contact_nodes 3 4 1e10 6", "contact_nodes 3 4 nan 6"}) {
    const std::size_t at = text.find("contact_nodes ");
    std::ofstream(checkpoint_path(dir)) << text.substr(0, at) << nodes << text.substr(text.find('\n', at));
    INFO(nodes);
    CHECK_THROWS_WITH(read_checkpoint(dir, cfg), Catch::Contains("contact_nodes must be one mesh node per contact node"));
  }
  fs::remove_all(dir);
}

TEST_CASE("the settings fingerprint: the same problem written differently is the same, every setting counts",
          "[restart]") {
  const std::string base = R"(
mesh = { size = [10.0, 5.0]; nx = 4; ny = 2; };
material = { E = 69000; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.3; };
loads = ( { node_set = "top_left"; type = "displacement"; component = "y"; value = 0.1; } );
time = { T = 1.0; };
output = { directory = "a"; };
)";
  const std::string fp = test::config_from_text(base).settings;
  // Sections reordered, 69000 as 6.9e4, CRLF line ends, a default spelled out, another directory.
  const std::string reordered = R"(
time = { T = 1.0; steps = 210; };
loads = ( { node_set = "top_left"; type = "displacement"; component = "y"; value = 0.1; } );
interface = { mu = 0.3; w = 0.01; Ct = 30.0; Cn = 50.0; boundary = "bottom"; alpha = 1.0; };
material = { nu = 0.3; E = 6.9e4; };
mesh = { nx = 4; ny = 2; size = [10.0, 5.0]; };
output = { directory = "b"; checkpoint_steps = 7; };
)";
  CHECK(test::config_from_text(reordered).settings == fp);
  CHECK(test::config_from_text(crlf(base)).settings == fp);
  CHECK(test::config_from_text(base, {"integrator.table=ARKODE_ARK436L2SA_DIRK_6_3_4"}).settings == fp);  // the default
  // Each setting that shapes the results changes it.
  // Each setting that shapes the results changes it, and a refused restart names it (the
  // setting as written where the hash's name is another: loads.type, not loads.kind).
  const std::string parts = test::config_from_text(base).settings_parts;
  const std::vector<std::pair<const char*, const char*>> changes{
      {"mesh.origin=[1.0,0.0]", "mesh.origin"}, {"mesh.size=[10.0,6.0]", "mesh.size"}, {"mesh.nx=5", "mesh.nx"},
      {"mesh.ny=3", "mesh.ny"}, {"mesh.element=Q4", "mesh.element"}, {"mesh.rotation=1.0", "mesh.rotation"},
      {"mesh.node_sets=({name=\"p\";box=[0.0,0.0,5.0,5.0];})", "mesh.node_sets"}, {"material.E=7e4", "material.E"},
      {"material.nu=0.25", "material.nu"}, {"material.hypothesis=plane_stress", "material.hypothesis"},
      {"interface.normal=[0.1,1.0]", "interface.normal"}, {"interface.Cn=51.0", "interface.Cn"},
      {"interface.Ct=31.0", "interface.Ct"}, {"interface.w=0.02", "interface.w"}, {"interface.alpha=2.0", "interface.alpha"},
      {"interface.mu=0.2", "interface.mu"}, {"interface.beta0=0.9", "interface.beta0"}, {"interface.g0=0.1", "interface.g0"},
      {"loads.[0].value=0.2", "loads.value"}, {"loads.[0].component=x", "loads.component"},
      {"loads.[0].node_set=top_right", "loads.node_set"}, {"loads.[0].type=force", "loads.type"}, {"time.T=2.0", "loads.value, time.T"},
      {"time.steps=100", "time.steps"}, {"solver.local_iterations=9", "solver.local_iterations"},
      {"solver.rho=paper", "solver.rho"}, {"solver.active_set=false", "solver.active_set"},
      {"solver.active_set_max_nodes=7", "solver.active_set_max_nodes"}, {"integrator.method=euler", "integrator.method"},
      {"integrator.scheme=erk", "integrator.scheme"}, {"integrator.table=ARKODE_SDIRK_5_3_4", "integrator.table"},
      {"integrator.initial_step=0.01", "integrator.initial_step"}, {"integrator.fixed_step=0.01", "integrator.fixed_step"},
      {"output.times=[0.5]", "output.times"}, {"output.watch=({name=\"B\";point=[0.0,0.0];})", "output.watch"},
      {"output.probes=({name=\"A\";point=[0.0,5.0];})", "output.probes"}};
  for (const auto& [change, name] : changes) {
    INFO(change);
    const Config other = test::config_from_text(base, {change});
    CHECK(other.settings != fp);
    const bool several = std::string(name).find(',') != std::string::npos;  // a value's ramp runs over [0, T]
    CHECK(differing_settings(parts, other.settings_parts) == std::string(name) + (several ? " differ" : " differs"));
  }
  CHECK(differing_settings(parts, test::config_from_text(base, {"mesh.nx=5", "interface.w=0.02"}).settings_parts) ==
        "interface.w, mesh.nx differ");
  CHECK(differing_settings(parts, "").empty());  // a checkpoint of format 6 keeps no digests
  // The numerical controls a failure message asks to change do not: a failed run restarts
  // with them changed.
  for (const char* control :
       {"solver.method=newton", "solver.form=jacobi", "solver.relaxation=0.5", "solver.over_relaxation=1.2", "solver.tolerance=1e-9", "solver.max_iterations=99", "solver.anderson=2",
        "solver.block_sweeps=3", "integrator.rtol=1e-7", "integrator.atol=1e-9", "integrator.max_step=0.1", "integrator.min_step=1e-6",
        "integrator.max_steps=99", "integrator.fixed_point_tolerance=1e-9", "integrator.fixed_point_iterations=9"}) {
    INFO(control);
    const Config changed = test::config_from_text(base, {control});
    CHECK(changed.settings == fp);
    // The controls have their own fingerprint: a sweep keeping a case run with others says so.
    CHECK(changed.controls_fingerprint() != test::config_from_text(base).controls_fingerprint());
  }
  // A 3D mesh's placement: each number of its origin and of its turn.
  const std::string box = R"(
mesh = { size = [4.0, 1.0, 4.0]; nx = 2; ny = 1; nz = 2; origin = [0.0, 0.0, 0.0]; rotation = { axis = [0.0, 1.0, 0.0]; angle = 10.0; }; };
material = { E = 69000; nu = 0.3; };
interface = { boundary = "bottom"; normal = [0.0, 1.0, 0.0]; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.3; };
loads = ( { node_set = "top_left_back"; type = "displacement"; component = "y"; value = 0.1; } );
time = { T = 1.0; };
)";
  const std::string fp3 = test::config_from_text(box).settings;
  for (const char* change : {"mesh.origin=[0.0,0.0,1.0]", "mesh.rotation.axis=[0.0,1.0,1.0]", "mesh.rotation.angle=11.0"}) {
    INFO(change);
    CHECK(test::config_from_text(box, {change}).settings != fp3);
  }
}

TEST_CASE("a restart keeps what the run said before it: the small-strain note once, at its first time", "[restart]") {
  // config/coating-curved.cfg lifted 4 mm notes that the coating leaves small strains at
  // t ~ 1.72 s; stopped at its first step after t = 2.5 s and restarted, the final report holds
  // that note once, with the time of the uninterrupted run's.
  const std::string whole = fs::temp_directory_path() / "rccm_notes_whole", parts = fs::temp_directory_path() / "rccm_notes_parts";
  const auto cfg = [](const std::string& dir) {
    return load_config(RCCM_SOURCE_DIR "/config/coating-curved.cfg",
                       {"loads.[0].value=4.0", "output.directory=\"" + dir + "\"", "output.checkpoint_steps=10"});
  };
  const RunResult reference = run(cfg(whole));
  REQUIRE(reference.warnings.size() == 1);
  const auto after = std::find_if(reference.steps.begin(), reference.steps.end(), [](const StepRecord& s) { return s.t > 2.5; });
  REQUIRE(after != reference.steps.end());
  request_stop(0);
  REQUIRE_THROWS_AS(run(cfg(parts), false, after->step), Interrupted);
  request_stop(0);
  REQUIRE(read_checkpoint(parts, cfg(parts)).notes.deformation_noted);
  const RunResult restarted = run(cfg(parts), true);
  CHECK(restarted.warnings == reference.warnings);
  CHECK_THAT(test::read_text(parts + "/report.txt"), Catch::Contains(reference.warnings[0]));
  fs::remove_all(whole);
  fs::remove_all(parts);
}
