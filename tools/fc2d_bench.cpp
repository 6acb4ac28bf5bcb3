// fc2d-bench FILE.dat...: the project's bipotential solver (Gauss-Seidel and Jacobi forms)
// against Siconos' fc2d NSGS on 2D frictional contact problems in Siconos' .dat format
// (e.g. ../shared/data/siconos-fc2d/). Per file: contacts, iterations, Siconos' error measure
// (fc2d_compute_error) of each solution, and time.
#include "rccm/bipotential_solver.hpp"
#include "rccm/errors.hpp"
#include "siconos_peer.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>

using namespace rccm;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: fc2d-bench FILE.dat...\n";
    return 2;
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a line per solver, even when interrupted
  const double tolerance = 1e-10;
  std::printf("%-42s %8s  %-14s %10s %12s %12s\n", "file", "contacts", "solver", "iterations", "error", "time [ms]");
  int status = 0;
  for (int a = 1; a < argc; ++a) {
    std::string name = argv[a];
    name = name.substr(name.find_last_of('/') + 1);
    try {
      const PlainContactProblem p = peer::read_dat(argv[a]);
      const ContactProblem pb = from_plain(p);
      for (SweepForm form : {SweepForm::GaussSeidel, SweepForm::Jacobi}) {
        SolverParams params;
        params.tolerance = tolerance;
        params.max_iterations = 100000;
        params.form = form;
        const auto start = std::chrono::steady_clock::now();
        const ContactSolution s = BipotentialSolver(params).solve(pb);
        const double ms = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%-42s %8d  %-14s %10d %12.3e %12.3f%s\n", name.c_str(), pb.size(),
                    form == SweepForm::GaussSeidel ? "bipotential-GS" : "bipotential-J", s.iterations,
                    peer::error(p, s.Rbar), ms, s.converged ? "" : "  (not converged)");
      }
      const peer::PeerSolution n = peer::solve(p, "nsgs", tolerance, 100000);
      std::printf("%-42s %8d  %-14s %10d %12.3e %12.3f%s\n", name.c_str(), pb.size(), "siconos-NSGS", n.iterations,
                  n.error, 1e3 * n.seconds, n.info == 0 ? "" : "  (not converged)");
    } catch (const std::exception& e) {
      std::printf("%-42s  failed: %s\n", name.c_str(), e.what());
      status = 1;
    }
  }
  return status;
}
