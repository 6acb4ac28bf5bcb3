// `rccm compare` (app/compare): the cases asked, each a full run; the contact solvers agree
// on beta; alpha = 0 is the rate-independent limit, as `rccm run` makes it.
#include "helpers.hpp"
#include "rccm/app/compare.hpp"
#include "rccm/io/run_report.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using namespace rccm;

TEST_CASE("compare: each integrator with each solver, the solvers agree on beta", "[compare]") {
  const Config cfg = load_config(test::shipped("b1.cfg"), {"time.T=2.0", "output.times=[1.0]"});
  const std::vector<CompareCase> cases = run_comparison(cfg, {"arkode", "euler"}, {"bipotential", "newton"}, 60);
  REQUIRE(cases.size() == 4);
  CHECK(cases[0].label == "arkode/bipotential");
  CHECK(cases[3].label == "euler/newton");
  CHECK(cases[1].config.integrator.method == Method::Arkode);
  CHECK(cases[2].config.integrator.method == Method::Euler);
  CHECK(cases[2].config.time.steps == 60);
  CHECK(cases[1].config.solver.method == ContactMethod::Newton);
  // The same integrator: Euler's same steps give beta to the solvers' tolerance; ARKODE
  // chooses its steps from the solves, and agrees to its own tolerance.
  std::ostringstream table;
  print_comparison(table, cases);
  CHECK_THAT(table.str(), Catch::Contains("total wall newton / bipotential: ") && !Catch::Contains("the paper: 161.7 s"));
  for (auto [k, tolerance] : {std::pair{0, 1e-4}, std::pair{2, 1e-8}}) {
    const Eigen::VectorXd &a = cases[k].result.snapshots.back().beta, &b = cases[k + 1].result.snapshots.back().beta;
    CHECK(a.minCoeff() < 0.5);  // debonding under way at T
    CHECK((a - b).cwiseAbs().maxCoeff() < tolerance);
  }
}

TEST_CASE("compare: the classical RCCM algorithm against the bipotential, beside the paper's ratios", "[compare]") {
  const Config cfg = load_config(test::shipped("b1.cfg"), {"time.T=2.0", "output.times=[1.0]"});
  const std::vector<CompareCase> cases = run_comparison(cfg, {"euler"}, {"bipotential", "rccm"}, 60);
  std::ostringstream table;
  print_comparison(table, cases);
  CHECK_THAT(table.str(), Catch::Contains("total wall rccm / bipotential: ") && Catch::Contains("(the paper: 161.7 s / 66.8 s = 2.4 on B1"));
}

TEST_CASE("compare: on B2 with ARKODE the classical rccm solver gives the bipotential solver's beta", "[compare]") {
  // A stable scheme: the solvers' differences (to their tolerance 1e-10) stay small. Under
  // Euler-210, unstable on B2 (dt C u^2 / alpha ~ 31), they grow to 20 % of beta by T.
  const std::vector<CompareCase> cases =
      run_comparison(load_config(test::shipped("b2.cfg")), {"arkode"}, {"bipotential", "rccm"}, 0);
  REQUIRE(cases.size() == 2);
  REQUIRE(cases[1].failure.empty());
  for (std::size_t k = 0; k < cases[0].result.snapshots.size(); ++k) {
    const Eigen::VectorXd &a = cases[0].result.snapshots[k].beta, &b = cases[1].result.snapshots[k].beta;
    INFO("t = " << cases[0].result.snapshots[k].t << ": |dbeta| " << (a - b).cwiseAbs().maxCoeff());
    CHECK((a - b).cwiseAbs().maxCoeff() <= 2e-8);  // measured 2.3e-9 at T, where beta <= 1.5e-6
  }
  CHECK(cases[1].result.solves.sweeps > 20 * cases[0].result.solves.sweeps);  // rccm's projected Gauss-Seidel ran
}

TEST_CASE("compare: the paper's step k on a fixed grid ends at k T / steps, output times off the grid aside", "[compare]") {
  // B1's t1 = 3.571 s and t2 = 5.143 s are 75 T / 210 and 108 T / 210 rounded: two more steps,
  // 212 in all; the table's column 100 is still the step that ends at 100 T / 210.
  const Config cfg = load_config(test::shipped("b1.cfg"), {"integrator.method=\"euler\"", "time.steps=210"});
  const RunResult r = Simulation(cfg).run();
  REQUIRE(r.steps.size() == 213);
  const std::vector<PaperColumn> columns = paper_table_columns(cfg, r);
  REQUIRE(columns.size() == 7);
  for (const PaperColumn& c : columns) {
    INFO("step " << c.step << " at t = " << c.record->t);
    CHECK(std::abs(c.record->t - cfg.time.T * c.step / 210) <= 1e-12);
  }
  CHECK(columns.back().step == 200);
  CHECK(columns.back().record->step == 202);  // the run's own count: after both output times
  // A run stopped at t = 5 s: the grid's steps it completed, 105 (the last column).
  RunResult stopped = r;
  stopped.steps.resize(107);  // t = 0, 105 grid steps, t1
  REQUIRE(stopped.steps.back().t == Approx(5.0));
  CHECK(paper_table_columns(cfg, stopped).back().step == 105);
  // With ARKODE a column is the k-th accepted step, no later than `last` (compared runs: one all reached).
  Config adaptive = cfg;
  adaptive.integrator.method = Method::Arkode;
  const RunResult a = Simulation(adaptive).run();
  const std::vector<PaperColumn> capped = paper_table_columns(adaptive, a, 139);
  CHECK(capped.back().step == 139);
  CHECK(capped.back().record == &a.steps[139]);
}

TEST_CASE("compare: alpha = 0 runs the rate-independent limit once per solver, as rccm run does", "[compare]") {
  const Config cfg = load_config(test::shipped("b1.cfg"), {"interface.alpha=0"});
  REQUIRE(cfg.integrator.method == Method::RateIndependent);
  const std::vector<CompareCase> cases = run_comparison(cfg, {"arkode", "euler"}, {}, 0);
  REQUIRE(cases.size() == 1);
  CHECK(cases[0].config.integrator.method == Method::RateIndependent);
  const RunResult run = Simulation(cfg).run();
  CHECK(cases[0].result.snapshots.back().beta == run.snapshots.back().beta);
  std::ostringstream table;
  print_comparison(table, cases);
  CHECK_THAT(table.str(), Catch::Contains("rate-independent"));
}

TEST_CASE("compare: the table's columns stay apart however long the cases' labels", "[compare]") {
  const Config cfg = load_config(test::shipped("b1.cfg"), {"time.T=0.5", "output.times=[0.25]"});
  const std::vector<CompareCase> cases = run_comparison(cfg, {"contact-only"}, {"bipotential", "newton"}, 20);
  std::ostringstream table;
  print_comparison(table, cases);
  std::istringstream lines(table.str());
  std::string header, word;
  std::getline(lines, header);
  std::istringstream words(header);
  std::vector<std::string> labels;
  while (words >> word) labels.push_back(word);
  CHECK(labels == std::vector<std::string>{"contact-only/bipotential", "contact-only/newton"});
  // every row's cells end under the labels, "max |beta - contact-only/bipotential|" too
  int rows = 0;
  for (std::string line; std::getline(lines, line) && !line.empty(); ++rows) CHECK(line.size() == header.size());
  CHECK(rows == 12);
}

TEST_CASE("compare: a case whose run fails says so, and the others are compared", "[compare]") {
  // ARKODE held to 3 steps cannot reach T; Euler's fixed steps do.
  const Config cfg = load_config(test::shipped("b1.cfg"), {"time.T=0.5", "output.times=[0.25]", "integrator.max_steps=3"});
  const std::vector<CompareCase> cases = run_comparison(cfg, {"arkode", "euler", "contact-only"}, {}, 20);
  REQUIRE(cases.size() == 3);
  CHECK_THAT(cases[0].failure, Catch::Contains("integrator.max_steps"));
  CHECK(cases[1].failure.empty());
  CHECK(cases[2].failure.empty());
  std::ostringstream table;
  print_comparison(table, cases);
  std::istringstream lines(table.str());
  std::string line;
  std::getline(lines, line);
  CHECK_THAT(line, Catch::StartsWith("arkode: run failed: "));
  while (std::getline(lines, line) && line.rfind(std::string(34, ' '), 0) != 0) continue;  // past the message
  std::istringstream words(line);
  std::vector<std::string> labels;
  for (std::string word; words >> word;) labels.push_back(word);
  CHECK(labels == std::vector<std::string>{"euler", "contact-only"});
}
