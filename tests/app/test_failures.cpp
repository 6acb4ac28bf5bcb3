// Failing solves (README "When a run fails"): each failure is caught where it happens, ARKODE
// first cuts its step, and a final failure says the step, the time, the node, the residual
// and what to change, with the results up to the last accepted step intact.
#include "helpers.hpp"
#include "rccm/time/beta_ode.hpp"
#include "rccm/io/checkpoint.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/app/simulation.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>

using namespace rccm;
namespace fs = std::filesystem;

namespace {

struct Failure {
  std::string message;
  int last_step = -1;  // the last accepted step the observer saw
};

/// Runs `cfg` into its output directory, expecting a SolveError: its message and the last
/// accepted step.
Failure run_to_failure(const Config& cfg) {
  Failure f;
  RunOptions o;
  o.write_files = true;
  o.force = true;
  o.observer = [&f](const AcceptedStep& a) { f.last_step = a.step; };
  try {
    Simulation(cfg, o).run();
  } catch (const SolveError& e) {
    f.message = e.what();
  }
  return f;
}

/// Every "contact node i (mesh node n at (x, y))" of `message` is pair i of the model of
/// `cfg`: n its mesh node, (x, y) that node's point. Returns how many there are.
int check_located(const std::string& message, const Config& cfg) {
  const Model model = test::make_model(cfg);
  const std::regex place(R"(contact node (\d+) \(mesh node (\d+) at \(([^,]+), ([^)]+)\)\))");
  int found = 0;
  for (std::sregex_iterator it(message.begin(), message.end(), place), end; it != end; ++it, ++found) {
    const int i = std::stoi((*it)[1]), n = std::stoi((*it)[2]);
    REQUIRE(i < model.contact_nodes());
    CHECK(model.interface().pairs[i].node == n);
    CHECK(std::stod((*it)[3]) == Approx(model.mesh().nodes[n].x()).margin(1e-12));
    CHECK(std::stod((*it)[4]) == Approx(model.mesh().nodes[n].y()).margin(1e-12));
  }
  return found;
}

/// B1 with Euler and a contact solver allowed too few sweeps (8, no exact active-set step):
/// the first steps converge, the solve fails once the debonding front starts to move.
Config starved_b1(const std::string& directory) {
  return load_config(RCCM_SOURCE_DIR "/config/b1.cfg",
                     {"solver.max_iterations=8", "solver.active_set=false", "integrator.method=\"euler\"",
                      "output.directory=\"" + directory + "\""});
}

/// Every line of a CSV file has the header's number of fields; returns the number of lines.
std::size_t complete_lines(const std::string& path) {
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  const auto fields = [](const std::string& l) { return std::count(l.begin(), l.end(), ','); };
  std::size_t n = 1;
  for (; std::getline(in, line); ++n) REQUIRE(fields(line) == fields(header));
  return n;
}

}  // namespace

TEST_CASE("a contact solve that does not converge stops the run and says where and what to change",
          "[failure]") {
  const std::string dir = fs::temp_directory_path() / "rccm_failure_contact";
  const Failure f = run_to_failure(starved_b1(dir));
  REQUIRE(f.last_step > 5);  // it failed halfway, not at the start
  const std::string step = "step " + std::to_string(f.last_step + 1) + ", t = ";
  CHECK_THAT(f.message, Catch::Contains(step));
  CHECK_THAT(f.message, Catch::Contains("did not converge in 8 sweeps (scaled residual"));
  CHECK_THAT(f.message, Catch::Contains("at contact node"));
  CHECK(check_located(f.message, starved_b1(dir)) == 1);
  CHECK_THAT(f.message, Catch::Contains("raise solver.max_iterations"));

  // The results up to the last accepted step are intact: one complete line per step, the
  // report says where the run stopped, a checkpoint holds that step.
  CHECK(complete_lines(dir + "/history.csv") == static_cast<std::size_t>(f.last_step + 2));
  CHECK(complete_lines(dir + "/curves.csv") == static_cast<std::size_t>(f.last_step + 2));
  std::ifstream report(dir + "/report.txt");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK_THAT(text, Catch::Contains("status: STOPPED"));
  CHECK_THAT(text, Catch::Contains("did not converge"));
  CHECK(read_checkpoint(dir, starved_b1(dir)).step == f.last_step);
  fs::remove_all(dir);
}

TEST_CASE("ARKODE cuts its step when a stage's contact solve fails, and says so when that is not enough",
          "[failure]") {
  // A bonded block pulled by a force: the adhesion wears off and the block comes loose.
  const std::string dir = fs::temp_directory_path() / "rccm_failure_arkode";
  const Config cfg =
      load_config(RCCM_SOURCE_DIR "/tests/stops/comes_loose_halfway.cfg", {"output.directory=\"" + dir + "\""});
  const Failure f = run_to_failure(cfg);
  REQUIRE(f.last_step > 20);
  // ARKODE retried with smaller steps (the failure was recoverable) before it gave up.
  CHECK_THAT(f.message, Catch::Contains("repeated recoverable right-hand side function errors"));
  CHECK_THAT(f.message, Catch::Contains("after step " + std::to_string(f.last_step)));
  CHECK_THAT(f.message, Catch::Contains("last contact failure: step " + std::to_string(f.last_step + 1) + ", t = "));
  CHECK_THAT(f.message, Catch::Contains("at contact node"));
  CHECK(check_located(f.message, cfg) >= 1);
  CHECK_THAT(f.message, Catch::Contains("more than the body's size"));
  CHECK_THAT(f.message, Catch::Contains("reduce the load"));
  CHECK(complete_lines(dir + "/history.csv") == static_cast<std::size_t>(f.last_step + 2));
  fs::remove_all(dir);
}

TEST_CASE("a fixed ARKODE step too long for its stages' Newton iteration says so, not to lower min_step", "[failure]") {
  // B1 in two fixed steps of 5 s: the stages' beta falls from 1 to 0 within one, Newton fails,
  // and a fixed step is not cut: the message names the setting to change.
  const std::string dir = fs::temp_directory_path() / "rccm_failure_fixed_step";
  const Failure f = run_to_failure(load_config(RCCM_SOURCE_DIR "/config/b1.cfg",
                                               {"output.directory=\"" + dir + "\"", "integrator.fixed_step=5.0"}));
  CHECK_THAT(f.message, Catch::Contains("the fixed step integrator.fixed_step = 5 s is too long for the Newton "
                                        "iteration of its stages here"));
  CHECK_THAT(f.message, !Catch::Contains("lower integrator.min_step"));
  fs::remove_all(dir);
}

TEST_CASE("a beta that is not finite stops the run where it appears: one out of [0, previous] is clamped and reported",
          "[failure]") {
  const Config cfg = test::config_from_text(R"(
mesh = { size = [4.0, 1.0]; nx = 4; ny = 1; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.2; };
loads = ( { node_set = "top"; type = "displacement"; component = "y"; value = 0.1; } );
time = { T = 1.0; };
)");
  Model model = test::make_model(cfg);
  BetaOde ode(model, make_contact_solver(cfg.solver));
  Eigen::VectorXd beta = model.initial_beta(), f(ode.size());
  ode.accept(0.0, beta);

  const auto message = [&](double t, double value, bool accept) {
    Eigen::VectorXd b = ode.committed().beta;
    b[2] = value;
    try {
      if (accept) ode.accept(t, b);
      else ode.rhs(t, b, f);
    } catch (const SolveError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  CHECK_THAT(message(0.5, nan, false),
             Catch::Contains("step 1, t = 0.5 s: the stage value of beta at contact node 2 (mesh node 2 at (2, 0)) is nan"));
  CHECK_THAT(message(0.5, -inf, false), Catch::Contains("(2, 0)) is -inf: the integrator diverged"));
  CHECK_THAT(message(0.5, nan, true), Catch::Contains("the accepted beta at contact node 2 (mesh node 2 at (2, 0)) is nan"));
  CHECK(ode.steps() == 0);  // nothing was committed
  // A stage value out of [0, 1] (a Newton iterate) is used clamped: no error.
  CHECK(message(0.5, -0.01, false) == "accepted");
  CHECK(message(0.5, 1.01, false) == "accepted");

  // Accepted values: round-off is clamped silently, more is clamped and reported.
  CHECK(message(0.2, 1 + 1e-9, true) == "accepted");
  CHECK(ode.committed().beta[2] == 1.0);
  CHECK(ode.warnings().empty());
  CHECK(message(0.4, 0.5, true) == "accepted");
  CHECK(message(0.6, 0.75, true) == "accepted");  // beta may not grow back
  CHECK(ode.committed().beta[2] == 0.5);
  CHECK(message(0.8, -0.01, true) == "accepted");
  CHECK(ode.committed().beta[2] == 0.0);
  REQUIRE(ode.warnings().size() == 1);
  CHECK_THAT(ode.warnings()[0],
             Catch::Contains("outside [0, previous beta] by up to 0.25 (contact node 2 (mesh node 2 at (2, 0)), t = 0.6 s)"));
}

TEST_CASE("a run that crawls says so, and ARKODE's hints follow the scheme in use", "[failure]") {
  // Steps capped at 5e-8 s on T = 1 s: after 100 of them the run notes that it crawls; at 150
  // ARKODE stops (max_steps) and, with its implicit scheme, does not suggest switching to it.
  const std::string dir = fs::temp_directory_path() / "rccm_failure_crawl";
  const Failure f = run_to_failure(load_config(
      RCCM_SOURCE_DIR "/config/b1.cfg", {"time.T=1.0", "output.times=[]", "integrator.max_step=5e-8",
                                         "integrator.max_steps=150", "output.directory=\"" + dir + "\""}));
  CHECK_THAT(f.message, Catch::Contains("TOO_MUCH_WORK") && Catch::Contains("raise integrator.max_steps") &&
                            !Catch::Contains("dirk"));
  std::ifstream report(dir + "/report.txt");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK_THAT(text, Catch::Contains("100 accepted steps in a row below 1e-7 T") && Catch::Contains("crawls"));
  fs::remove_all(dir);
}
