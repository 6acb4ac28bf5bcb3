// The ODE of the adhesion intensity (MODEL.md s6, paper eq. 31): one state per contact node,
//   d beta_i / dt = f_i(t, beta) = -(1/alpha) max(0, (Cn u_n,i^2 + Ct u_t,i^2) beta_i - w),
// where u comes from one bipotential contact solve at (t, beta) that starts from the last
// ACCEPTED state. After each accepted step the contact state is recomputed at the accepted
// (t, beta) and committed. Every integrator (ARKODE, Euler, rate-independent) works on this.
#pragma once

#include "rccm/bipotential_solver.hpp"
#include "rccm/interface_state.hpp"
#include "rccm/model.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace rccm {

/// Work counted over contact solves.
struct SolveCounts {
  long contact_solves = 0;
  long sweeps = 0;
  int max_sweeps = 0;
  double seconds = 0;  // wall time inside the contact solves (problem set-up and bipotential solver)
  void add(const ContactSolution& s, double solve_seconds);
};

/// What an observer sees after each accepted step.
struct AcceptedStep {
  int step = 0;         // 0 is the initial state at t = 0
  double t = 0, dt = 0;
  const InterfaceState& state;
  const ContactSolution& solution;  // the commit solve
  ContactResiduals residuals;       // its Signorini-Coulomb residuals
  SolveCounts counts;               // solves of this step (stages and commit)
  double cpu_seconds = 0;           // wall time of this step
};

class BetaOde {
 public:
  using Observer = std::function<void(const AcceptedStep&)>;

  BetaOde(const Model& model, const SolverParams& solver, Observer observer = {});

  int size() const { return model_.contact_nodes(); }
  const Model& model() const { return model_; }
  const InterfaceState& committed() const { return committed_; }
  const SolveCounts& totals() const { return totals_; }
  int steps() const { return step_; }

  /// How far an accepted beta may leave [0, previous beta] (round-off of the scheme's sums)
  /// before warnings() reports it.
  static constexpr double beta_slack = 1e-6;

  /// The largest amount by which an accepted beta left [0, previous beta] before clamping.
  struct Excursion {
    double size = 0, t = 0;
    int node = -1;
  };

  /// f(t, beta) into `f`; throws SolveError when the contact solve fails or beta is not
  /// finite (ARKODE then cuts the step).
  const ContactSolution& rhs(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> f);

  /// Cn u_n^2 + Ct u_t^2 per node (the opening energy density without beta), N/mm.
  Eigen::VectorXd opening_energy(const ContactSolution& s) const;

  /// df_i / dbeta_i = -(Cn u_n^2 + Ct u_t^2)/alpha where damage is active, 0 elsewhere:
  /// the modified-Newton matrix of MODEL.md s6 (u held fixed), at (t, beta).
  Eigen::VectorXd jacobian_diagonal(double t, const Eigen::VectorXd& beta);

  /// Accepts (t, beta): clamps beta to [0, committed beta] (in place), solves the contact
  /// at the accepted state, commits it and notifies the observer.
  void accept(double t, Eigen::Ref<Eigen::VectorXd> beta);

  /// Takes up a run from a checkpoint: `state` becomes the committed state after `step`
  /// accepted steps and `totals` solves (no solve, no observer call).
  void resume(const InterfaceState& state, int step, const SolveCounts& totals);

  /// What the user must know: an accepted beta that left [0, previous beta] by more than
  /// beta_slack (clamped).
  std::vector<std::string> warnings() const;
  const Excursion& excursion() const { return excursion_; }
  void restore(const Excursion& e) { excursion_ = e; }

 private:
  const ContactSolution& solve(double t, const Eigen::VectorXd& beta);
  /// Throws SolveError naming the step, t and the first node whose beta is NaN or Inf.
  void check_finite(double t, const Eigen::VectorXd& beta, const char* what) const;

  const Model& model_;
  BipotentialSolver solver_;
  Observer observer_;
  InterfaceState committed_;
  double alpha_, w_, Cn_, Ct_;
  // The last solve, reused when the Jacobian is asked at the same (t, beta).
  double last_t_ = -1;
  Eigen::VectorXd last_beta_;
  ContactSolution last_;
  SolveCounts totals_, step_counts_;
  int step_ = -1;
  Excursion excursion_;
  double step_start_ = 0;  // wall clock at the previous accepted step
};

}  // namespace rccm
