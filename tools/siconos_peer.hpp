// Siconos numerics (Debian libsiconos-numerics-dev) as an independent peer for the contact
// step: its fc2d and fc3d solvers and error measures on our plain contact problems. Siconos
// orders each contact normal first; ours puts it last: the reordering happens here only.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/contact/contact_problem.hpp"
#include "rccm/contact/delassus.hpp"
#include "rccm/model/model.hpp"

#include <string>
#include <vector>

namespace rccm::peer {

struct PeerSolution {
  Eigen::VectorXd R;   // (t, n) per contact
  int iterations = 0;
  double error = 0;    // Siconos' own error measure at the end
  int info = 0;        // 0: Siconos says converged
  double seconds = 0;
};

/// Reads a Siconos .dat frictional contact problem (dimension 2) into the plain form.
PlainContactProblem read_dat(const std::string& path);

/// Solves with fc2d_driver: "nsgs", "lemke" or "enum"; 3D problems with fc3d_driver: "nsgs"
/// or "nsn" (semi-smooth Newton on the Alart-Curnier function).
PeerSolution solve(const PlainContactProblem& p, const std::string& solver, double tolerance, int max_iterations);

/// fc2d_compute_error (3D: fc3d_compute_error) of a solution R (our order), normalised by |q|.
double error(const PlainContactProblem& p, const Eigen::VectorXd& R);

/// A condensed contact problem of a run: the one its commit solve met at an accepted step.
struct StepProblem {
  int step = 0;
  double t = 0;
  ContactProblem problem;       // as the run poses it (springs, gap, previous slip); points into the model
  Eigen::VectorXd Rbar_before, u_before;  // the previous accepted step's solution: the run's warm start
  PlainContactProblem plain;    // the same in Siconos' plain form
};

/// Runs `cfg` (no files) and returns the contact problems of every `every`-th accepted step.
std::vector<StepProblem> step_problems(const Model& model, const Config& cfg, int every);

}  // namespace rccm::peer
