// The beta ODE of the RCCM interface (docs/MODEL.md s6, paper eq. 31), one state per contact pair:
//   d beta_i / dt = f_i(t, beta) = -(1/alpha) max(0, (Cn u_n,i^2 + Ct |u_t,i|^2) beta_i - w),
// where u comes from one contact solve at (t, beta) that starts from the last ACCEPTED
// state. After each accepted step the contact state is recomputed at the accepted (t, beta),
// committed, and shown to the observer.
#pragma once

#include "rccm/contact/contact_solver.hpp"
#include "rccm/model/interface_state.hpp"
#include "rccm/model/model.hpp"
#include "rccm/time/beta_system.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rccm {

/// Work counted over contact solves.
struct SolveCounts {
  long contact_solves = 0;
  long sweeps = 0;
  int max_sweeps = 0;
  double seconds = 0;  // wall time inside the contact solves (problem set-up and solver)
  long condensations = 0;       // W0's springs set anew (Model::condense; solver.springs_follow_beta)
  double condense_seconds = 0;  // wall time of those
  // ContactSolution's timed and threaded sweeps, of this process (not in a checkpoint: since
  // a restart, as its wall time).
  long timed_sweeps = 0, threaded_sweeps = 0;
  void add(const ContactSolution& s, double solve_seconds);
  double sweeps_per_solve() const { return double(sweeps) / double(std::max(1L, contact_solves)); }
};

/// What an observer sees after each accepted step.
struct AcceptedStep {
  int step = 0;  // 0 is the initial state at t = 0
  double t = 0, dt = 0;
  const InterfaceState& state;
  const ContactSolution& solution;  // the commit solve
  ContactResiduals residuals;       // its Signorini-Coulomb residuals
  SolveCounts counts;               // solves of this step (stages and commit)
  double wall_seconds = 0;          // wall time since the last step was accepted
  const InterfaceState* midpoint = nullptr;  // the state halfway through the step (track_midpoints)
};

class BetaOde final : public BetaSystem {
 public:
  using Observer = std::function<void(const AcceptedStep&)>;

  /// `model`'s W0 springs follow beta (Model::condense) after an accepted step where they lag it.
  BetaOde(Model& model, std::unique_ptr<ContactSolver> solver, Observer observer = {});

  int size() const override { return model_.contact_nodes(); }
  double committed_time() const override { return committed_.t; }
  const Eigen::VectorXd& committed_beta() const override { return committed_.beta; }
  int steps() const override { return step_; }

  /// Throws SolveError when the contact solve fails or beta is not finite.
  void rhs(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> f) override;
  void jacobian_diagonal(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> J) override;
  void rate_independent_beta(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> out) override;
  /// Also solves the contact at the accepted state, commits it and notifies the observer.
  void accept(double t, Eigen::Ref<Eigen::VectorXd> beta) override;
  std::string locate(int i) const override { return model_.locate(i); }

  /// From now on each accepted step also gives the state halfway through it: beta from the
  /// cubic Hermite interpolant of (beta, f) at both ends (the accuracy of a 4th-order scheme),
  /// the contact solved there by `solver` (its own, so that the run's solves are untouched).
  /// The energy balance integrates over it to the scheme's order (EnergyBalance).
  void track_midpoints(std::unique_ptr<ContactSolver> solver);

  const Model& model() const { return model_; }
  const InterfaceState& committed() const { return committed_; }
  const SolveCounts& totals() const { return totals_; }

  /// How far an accepted beta may leave [0, previous beta] (round-off of the scheme's sums)
  /// before warnings() reports it.
  static constexpr double beta_slack = 1e-6;

  /// The largest amount by which an accepted beta left [0, previous beta] before clamping.
  struct Excursion {
    double size = 0, t = 0;
    int node = -1;
  };

  /// Takes up a run from a checkpoint: `state` becomes the committed state after `step`
  /// accepted steps and `totals` solves, with the excursion seen so far, the model condensed
  /// with its springs at `springs_beta` as when the checkpoint was written (no solve, no
  /// observer call).
  void resume(const InterfaceState& state, int step, const SolveCounts& totals, const Excursion& excursion,
              const Eigen::VectorXd& springs_beta);

  /// What the user must know: an accepted beta that left [0, previous beta] by more than
  /// beta_slack (clamped).
  std::vector<std::string> warnings() const;
  const Excursion& excursion() const { return excursion_; }

 private:
  const ContactSolution& solve(double t, const Eigen::VectorXd& beta);
  /// The state halfway from the committed one to (t, beta) whose contact solution is s.
  InterfaceState midpoint(double t, const Eigen::VectorXd& beta, const ContactSolution& s);
  /// d beta / dt at a state: the law at its displacement.
  Eigen::VectorXd rate_at(const Eigen::VectorXd& beta, const Eigen::VectorXd& u) const;
  /// Throws SolveError naming the step, t and the first pair whose beta is NaN or Inf.
  void check_finite(double t, const Eigen::VectorXd& beta, const char* what) const;
  /// The model condensed with its springs at `springs_beta`; the committed and midpoint states'
  /// y = Rbar + E u follow the new E, the solvers drop what they kept of the old W0.
  void condense(const Eigen::VectorXd& springs_beta);

  Model& model_;
  std::unique_ptr<ContactSolver> solver_;
  Observer observer_;
  InterfaceState committed_;
  // The last solve, reused when asked again at the same (t, beta).
  double last_t_ = -1;
  Eigen::VectorXd last_beta_;
  ContactSolution last_;
  SolveCounts totals_, step_counts_;
  int step_ = -1;
  Excursion excursion_;
  double step_start_ = 0;  // wall clock at the previous accepted step
  std::unique_ptr<ContactSolver> midpoint_solver_;
  InterfaceState midpoint_;
};

}  // namespace rccm
