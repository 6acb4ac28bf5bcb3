// The ODE of the adhesion intensity as the integrators see it (docs/MODEL.md s6):
//   d beta / dt = f(t, beta),  one state per contact pair,
// with a committed (accepted) state that only accept() moves. The integrators are written
// against this interface alone (as MFEM's ODESolver sees a TimeDependentOperator), so they
// are tested on a scalar ODE without a mesh; BetaOde is the RCCM interface's system.
#pragma once

#include <Eigen/Core>

#include <string>

namespace rccm {

class BetaSystem {
 public:
  virtual ~BetaSystem() = default;

  virtual int size() const = 0;

  /// The last accepted time and beta, and how many steps have been accepted (step 0 is the
  /// initial state; a restarted run counts the steps before its checkpoint).
  virtual double committed_time() const = 0;
  virtual const Eigen::VectorXd& committed_beta() const = 0;
  virtual int steps() const = 0;

  /// f(t, beta) into `f`; throws SolveError when it cannot be evaluated (the integrator then
  /// cuts its step).
  virtual void rhs(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> f) = 0;

  /// df_i / dbeta_i at (t, beta): the modified-Newton matrix of an implicit scheme, and
  /// -dt J_ii the stability ratio of an explicit one.
  virtual void jacobian_diagonal(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> J) = 0;

  /// The rate-independent limit alpha -> 0 (docs/MODEL.md s3): per pair, the largest beta not
  /// above the committed one at which damage stops growing, at the state of (t, beta).
  virtual void rate_independent_beta(double t, const Eigen::VectorXd& beta, Eigen::Ref<Eigen::VectorXd> out) = 0;

  /// Accepts (t, beta): beta is clamped to [0, committed beta] in place (it never increases)
  /// and becomes the committed state.
  virtual void accept(double t, Eigen::Ref<Eigen::VectorXd> beta) = 0;

  /// Node i in a message (Model::locate: where it is in the results).
  virtual std::string locate(int i) const { return "contact node " + std::to_string(i); }
};

}  // namespace rccm
