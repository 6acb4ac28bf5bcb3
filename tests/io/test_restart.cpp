// Interrupted runs and restart (README "Interrupted runs and restart"): a run stopped by a
// signal writes a checkpoint; `--restart` from it gives what the uninterrupted run gives.
#include "helpers.hpp"
#include "rccm/io/checkpoint.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/app/stop_request.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>

using namespace rccm;
namespace fs = std::filesystem;

namespace {

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
  const Case cases[] = {{{"integrator.method=\"euler\"", "time.steps=300"}, 170, 1e-9},
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
    CHECK(ck.state.t < 10.0);
    const RunResult restarted = run(b1(parts, c.settings), true);

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
    // The files hold each accepted step once: what the stopped run wrote after its
    // checkpoint was replaced, not repeated.
    CHECK(restarted.steps.size() == static_cast<std::size_t>(restarted.integrator.steps + 1));
    CHECK(lines(parts + "/history.csv") == restarted.steps.size() + 1);
    CHECK(lines(parts + "/curves.csv") == restarted.steps.size() + 1);
    if (c.tolerance < 1e-8) {
      CHECK(restarted.integrator.steps == reference.integrator.steps);
      CHECK(lines(parts + "/history.csv") == lines(whole + "/history.csv"));
    }
    CHECK(!fs::exists(parts + "/mesh_" + std::string("0004.vtu")));  // three output times and T
    fs::remove_all(whole);
    fs::remove_all(parts);
  }
}

TEST_CASE("a checkpoint reads back bit for bit", "[restart]") {
  const std::string dir = fs::temp_directory_path() / "rccm_checkpoint_bits";
  fs::create_directories(dir);
  const Config cfg = b1(dir, {});
  Checkpoint c;
  c.settings = cfg.settings;
  c.step = 123;
  c.last_step = 1.0 / 3.0;
  c.state.t = 2.0 / 7.0;
  c.state.beta = Eigen::VectorXd::Random(5).cwiseAbs();
  c.state.beta[0] = 4.9406564584124654e-324;  // the smallest subnormal
  c.state.Rbar = Eigen::VectorXd::Random(10) * 1e-300;
  c.state.u = Eigen::VectorXd::Random(10) * 1e300;
  c.state.y = Eigen::VectorXd::Random(10);
  c.state.status = {Status::Stick, Status::Slide, Status::Separated, Status::Stick, Status::Slide};
  c.energy = {1.0 / 3, 2.0 / 3, -1e-17, 3.5, 0.1, -0.0};
  c.diagnostics = {44.95, 7};
  c.excursion = {0.25, 0.6, 2};
  c.progress.peak_force = {203.51, -1e-9};
  c.progress.peak_time = {0.3, 0.0};
  c.progress.solves = {35443, 87000, 7, 1.25};
  c.progress.integrator = {1616, 616, 35443, 30000};
  c.progress.steps = {{0, 0.0, 0.0, 1, 2.0, 2, 1e-4}, {1, 1e-3, 1e-3, 21, 2.47, 7, 9.5e-4}};
  c.progress.snapshots = {{3.571, c.state.beta, c.state.Rbar, c.state.u, 11.7}};
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
  CHECK(r.progress.peak_force == c.progress.peak_force);
  CHECK(r.progress.solves.sweeps == c.progress.solves.sweeps);
  CHECK(r.progress.integrator.rejected == c.progress.integrator.rejected);
  REQUIRE(r.progress.steps.size() == 2);
  CHECK(r.progress.steps[1].sweeps_mean == 2.47);
  REQUIRE(r.progress.snapshots.size() == 1);
  CHECK(r.progress.snapshots[0].u == c.state.u);
  CHECK(r.progress.snapshots[0].debonded_length == 11.7);
  CHECK_FALSE(fs::exists(checkpoint_path(dir) + ".tmp"));
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
  c.state.beta = Eigen::VectorXd::Ones(2);
  c.state.Rbar = c.state.u = c.state.y = Eigen::VectorXd::Zero(4);
  c.state.status.assign(2, Status::Separated);
  write_checkpoint(dir, c);
  CHECK(message(cfg) == "no error");
  // Another alpha is another run; the output directory and checkpoint interval are not.
  CHECK_THAT(message(b1(dir, {"interface.alpha=2.0"})), Catch::Contains("written by a run of other settings"));
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
  fs::remove_all(dir);
}
