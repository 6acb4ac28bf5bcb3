// fc2d-bench [--benchmarks CONFIG_DIR] [--copies K] [FILE.dat...]: the project's contact solvers (bipotential
// in its Gauss-Seidel and Jacobi forms, rccm, newton) against Siconos' fc2d NSGS on 2D frictional contact
// problems: Siconos .dat files (e.g. ../shared/data/siconos-fc2d/) and, with --benchmarks,
// the condensed problems that B1 and B2 (Euler-210) solve at every 40th step, and in 3D
// those of the corner peel (config/corner-peel.cfg, Euler-210) against Siconos' fc3d NSGS.
// Per problem and solver: iterations, Siconos' error measure (fc2d_compute_error) of the
// solution, time per solve, and Siconos' time over each solver's: Siconos is asked for the
// error our default (bipotential Gauss-Seidel) solve reached, or 1e-10 (our tolerance) where
// it went below that (Siconos cannot always reach round-off; docs/PERFORMANCE.md "The three contact
// solvers against Siconos").
// In 2D, where Siconos converges, the row "GS at Siconos' its": our plain Gauss-Seidel sweeps on
// Siconos' own problem (for B1 and B2 the plain form, springs folded in), exactly as many as
// its NSGS took. They are its iterations (the same reactions, tests/peer/test_siconos_peer.cpp),
// so the same error: the ratio is the cost of an iteration, the algorithm being the same.
// --copies K poses each later sparse file K times over, as K independent problems in one
// (W block-diagonal): a size test of the sparse path (the solution is K copies of one).
//
// What is timed, per solve (each side's calls repeated until 50 ms have passed):
// - ours, cold: one call of the timed lambda, the loop's clock read and std::function call
//   included: forget_W0() (the exact step's factorization, rccm's inverse of W0: nothing
//   factorized by the previous call serves this one), then solve(pb, {}, {}) from zero: the
//   pairs' blocks, the sweeps, exact steps and verifying passes, the solution's vectors, and
//   its move into the caller's (freeing the previous call's). Not timed: constructing the
//   solver (make_contact_solver, once per row, as a run builds its solver once), reading and
//   posing the problem, the error measure. The bipotential solver keeps its scratch vectors'
//   memory from call to call, as in a run (not their contents: each solve sets them afresh).
//   Warm rows: solve() from the previous step's solution by a solver that keeps its
//   factorization, as in a run.
// - Siconos: the time between two clock reads around fc2d_driver / fc3d_driver (peer::solve):
//   its NSGS from zero, with whatever the driver allocates. Not timed: the copy of the problem
//   into Siconos' storage, solver_options_create / delete, the reaction and velocity arrays
//   (allocated and zeroed before), the reordering of the result, the error measure.
#include "rccm/contact/contact_solver.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/fem/mesh_source.hpp"
#include "rccm/io/config_reader.hpp"
#include "siconos_peer.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <vector>

using namespace rccm;

namespace {

/// Seconds per call of `f`, repeated until 50 ms have passed (tiny problems time badly once).
double seconds_per_call(const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  int calls = 0;
  double elapsed = 0;
  do {
    f();
    ++calls;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (elapsed < 0.05 && calls < 100000);
  return elapsed / calls;
}

/// Siconos' NSGS at `tolerance`: its solution, and the time inside its driver per call (the
/// copy of the problem into Siconos' storage is not counted), repeated like ours.
double siconos_nsgs(const PlainContactProblem& p, double tolerance, peer::PeerSolution& n) {
  double inside = 0;
  int calls = 0;
  seconds_per_call([&] {
    n = peer::solve(p, "nsgs", tolerance, 100000);
    inside += n.seconds;
    ++calls;
  });
  return inside / calls;
}

/// Seconds per cold solve of `pb` from zero by one solver of `params`, built outside the timing
/// and made to forget W0 before every solve; `s`: the solution.
double cold_seconds(const SolverParams& params, const ContactProblem& pb, ContactSolution& s) {
  const std::unique_ptr<ContactSolver> solver = make_contact_solver(params);
  return seconds_per_call([&] {
    solver->forget_W0();
    s = solver->solve(pb, {}, {});
  });
}

void row(const std::string& name, int contacts, const char* solver, int iterations, double error, double seconds,
         double ratio, bool converged) {
  std::printf("%-42s %8d  %-19s %10d %12.3e %12.4f %10s%s\n", name.c_str(), contacts, solver, iterations, error,
              1e3 * seconds, ratio > 0 ? std::to_string(ratio).substr(0, 6).c_str() : "", converged ? "" : "  (not converged)");
}

/// One of our solvers as the bench runs it: its name in the table and its settings.
struct Contender {
  const char* name;
  ContactMethod method;
  SweepForm form;
};
constexpr Contender contenders[] = {{"bipotential-GS", ContactMethod::Bipotential, SweepForm::GaussSeidel},
                                    {"bipotential-J", ContactMethod::Bipotential, SweepForm::Jacobi},
                                    {"rccm", ContactMethod::Rccm, SweepForm::GaussSeidel},
                                    {"newton", ContactMethod::Newton, SweepForm::GaussSeidel}};

/// Where our default solve does not converge (a hyperstatic granular snapshot, W singular:
/// Siconos' NSGS does not either), the time each takes to the error Siconos' NSGS reaches at
/// its tolerance 1e-6, if it reaches that: ours with the fewest sweeps (to 10 %) that reach it.
void to_siconos_error(const std::string& name, const PlainContactProblem& p, const ContactProblem& pb, SolverParams params) {
  peer::PeerSolution n;
  const double siconos_seconds = siconos_nsgs(p, 1e-6, n);
  if (n.info != 0) return;
  params.tolerance = 1e-10;
  ContactSolution s;
  const auto reaches = [&](int sweeps) {
    params.max_iterations = sweeps;
    s = make_contact_solver(params)->solve(pb, {}, {});
    return peer::error(p, s.Rbar) <= n.error;
  };
  int enough = 100;
  while (!reaches(enough) && enough < 100000) enough *= 2;
  for (int fewer = enough / 2; enough - fewer > enough / 10;) {
    const int mid = (fewer + enough) / 2;
    (reaches(mid) ? enough : fewer) = mid;
  }
  params.max_iterations = enough;
  const double seconds = cold_seconds(params, pb, s);
  const std::string label = name + " to Siconos' error at 1e-6";
  row(label, pb.size(), "bipotential-GS", enough, peer::error(p, s.Rbar), seconds, siconos_seconds / seconds, true);
  row(label, pb.size(), "siconos-NSGS", n.iterations, n.error, siconos_seconds, 1.0, n.info == 0);
}

/// Our plain Gauss-Seidel sweeps (no extrapolation, no exact step) on the problem Siconos is
/// given (the plain form), as many as Siconos' NSGS took: they are its iterations (the same
/// reactions after each, to round-off: tests/peer), so the same error, and the ratio is the
/// cost of an iteration. A tolerance no sweep reaches keeps them going; a problem solved
/// exactly (every pair's residual 0) stops sooner.
void same_iterations_row(const std::string& name, const PlainContactProblem& p, const peer::PeerSolution& n,
                         double siconos_seconds) {
  SolverParams params;
  params.tolerance = 1e-30;
  params.max_iterations = n.iterations;
  params.anderson = 0;
  params.active_set = false;
  ContactSolution s;
  const double seconds = cold_seconds(params, from_plain(p), s);
  row(name, p.mu.size(), "GS at Siconos' its", s.iterations, peer::error(p, s.Rbar), seconds, siconos_seconds / seconds,
      true);
}

/// Each of our solvers cold from zero, then Siconos NSGS at the error our default solve
/// (bipotential Gauss-Seidel) reached; the last column is Siconos' time over each solver's.
/// `settings`: the config's solver section (sweeps alone or the exact step, ...), else defaults.
/// Returns Siconos' time per solve.
double compare(const std::string& name, const PlainContactProblem& p, const ContactProblem& pb, const SolverParams& settings = {}) {
  struct Measured {
    const char* name;
    ContactSolution s;
    double error, seconds;
  };
  std::vector<Measured> ours;
  for (const Contender& c : contenders) {
    SolverParams params = settings;
    params.tolerance = 1e-10;
    params.max_iterations = 100000;
    params.method = c.method;
    params.form = c.form;
    Measured m{c.name, {}, 0, 0};
    try {
      m.seconds = cold_seconds(params, pb, m.s);
    } catch (const SolveError& e) {  // a solver that cannot take this problem says why
      std::printf("%-42s %8d  %-14s  cannot: %s\n", name.c_str(), pb.size(), c.name, e.what());
      continue;
    }
    m.error = peer::error(p, m.s.Rbar);
    ours.push_back(m);
  }
  if (!ours.empty() && !ours.front().s.converged) to_siconos_error(name, p, pb, settings);
  const double target = std::max(ours.front().error, 1e-10);
  peer::PeerSolution n;
  const double seconds = siconos_nsgs(p, target, n);
  for (const Measured& m : ours)
    row(name, pb.size(), m.name, m.s.iterations, m.error, m.seconds, seconds / m.seconds, m.s.converged);
  row(name, pb.size(), "siconos-NSGS", n.iterations, n.error, seconds, 1.0, n.info == 0);
  if (p.dim == 2 && n.info == 0) same_iterations_row(name, p, n, seconds);
  // Siconos solves the plain form, springs folded in: (I - W0 E)^-1 W0, a dense solve of m
  // right-hand sides that our solvers do without (their springs stay in the local solve).
  // Where the problem has springs, building that form is part of solving it with Siconos.
  if (!pb.Dref.isZero(0.0)) {
    PlainContactProblem built;
    const double form_seconds = seconds_per_call([&] { built = plain_form(pb); });
    row(name, pb.size(), "siconos+form", n.iterations, n.error, seconds + form_seconds,
        (seconds + form_seconds) / ours.front().seconds, n.info == 0);
  }
  return seconds;
}

/// The solve as a run makes it: warm-started from the previous accepted step's solution by
/// the solver that solved before (it keeps its factorization). Siconos' NSGS is run without a
/// warm start (it starts from zero), so its cold time is the comparison.
void warm_row(const std::string& name, const peer::StepProblem& sp, double siconos_seconds, SolverParams params) {
  params.tolerance = 1e-10;
  params.max_iterations = 100000;
  const std::unique_ptr<ContactSolver> solver = make_contact_solver(params);
  ContactSolution s;
  const double seconds = seconds_per_call([&] { s = solver->solve(sp.problem, sp.Rbar_before, sp.u_before); });
  row(name, sp.problem.size(), "bipotential-GS warm", s.iterations, peer::error(sp.plain, s.Rbar), seconds,
      siconos_seconds / seconds, s.converged);
}

/// K independent copies of a sparse problem in one: W block-diagonal, q and mu repeated.
PlainContactProblem copies(const PlainContactProblem& p, int K) {
  const auto* sparse = dynamic_cast<const SparseDelassus*>(p.W.get());
  if (!sparse || K == 1) return p;
  const Eigen::SparseMatrix<double>& W = sparse->matrix();
  const Eigen::Index m = W.rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(K) * W.nonZeros());
  for (int k = 0; k < K; ++k)
    for (Eigen::Index j = 0; j < m; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(W, j); it; ++it)
        entries.emplace_back(int(k * m + it.row()), int(k * m + j), it.value());
  Eigen::SparseMatrix<double> WK(K * m, K * m);
  WK.setFromTriplets(entries.begin(), entries.end());
  return {p.dim, std::make_shared<SparseDelassus>(std::move(WK)), p.q.replicate(K, 1), p.mu.replicate(K, 1)};
}

}  // namespace

const char* const usage =
    "usage: fc2d-bench [--benchmarks CONFIG_DIR] [--copies K] [FILE.dat...]\n"
    "Our contact solvers (bipotential Gauss-Seidel and Jacobi, rccm, newton) against Siconos' NSGS, one row\n"
    "per problem and solver: iterations, Siconos' error, ms per solve, Siconos' time over ours; in 2D also\n"
    "\"GS at Siconos' its\": our plain sweeps, exactly as many as Siconos' iterations (the same iterates).\n"
    "  FILE.dat            a Siconos fc2d problem (Siconos' numerics/src/FrictionContact/test/data/)\n"
    "  --benchmarks DIR    B1's and B2's condensed problems at every 40th step of Euler-210, and in 3D the\n"
    "                      corner peel's against fc3d NSGS (DIR/b1.cfg, b2.cfg, corner-peel.cfg)\n"
    "  --copies K          each later sparse file posed K times over in one problem (a size test)\n"
    "  --help, -h          this text\n";

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << usage;
    return 2;
  }
  for (int a = 1; a < argc; ++a)
    if (std::strcmp(argv[a], "--help") == 0 || std::strcmp(argv[a], "-h") == 0) {
      std::cout << usage;
      return 0;
    }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a line per solver, even when interrupted
  std::printf("%-42s %8s  %-19s %10s %12s %12s %10s\n", "problem", "contacts", "solver", "iterations", "error",
              "ms/solve", "siconos/it");
  int status = 0, K = 1;
  for (int a = 1; a < argc; ++a) {
    try {
      if (std::strcmp(argv[a], "--benchmarks") == 0 && a + 1 < argc) {
        const std::string dir = argv[++a];
        for (const char* file : {"b1", "b2", "corner-peel"}) {
          const Config cfg = load_config(dir + "/" + file + ".cfg", {"integrator.method=euler", "time.steps=210"});
          const Model model(cfg, make_mesh(cfg));
          for (const peer::StepProblem& sp : peer::step_problems(model, cfg, 40)) {
            const std::string label = std::string(file) + " step " + std::to_string(sp.step);
            warm_row(label, sp, compare(label, sp.plain, sp.problem, cfg.solver), cfg.solver);
          }
        }
        continue;
      }
      if (std::strcmp(argv[a], "--copies") == 0 && a + 1 < argc) {
        K = std::max(1, std::atoi(argv[++a]));
        continue;
      }
      std::string name = argv[a];
      name = name.substr(name.find_last_of('/') + 1);
      PlainContactProblem p = copies(peer::read_dat(argv[a]), K);
      if (p.W->dense() == nullptr && K > 1) name += " x" + std::to_string(K);
      // A problem at round-off scale (the granular snapshot at rest: |q| = 4e-18) is scaled to
      // |q| = 1: its solution scales with q, and Siconos' error measure is absolute below
      // |q| = eps (it accepts R = 0 there at once).
      if (p.q.norm() < 1e-12) {
        p.q /= p.q.norm();
        name += " (q scaled to |q| = 1)";
      }
      compare(name, p, from_plain(p));
    } catch (const std::exception& e) {
      std::printf("%-42s  failed: %s\n", argv[a], e.what());
      status = 1;
    }
  }
  return status;
}
