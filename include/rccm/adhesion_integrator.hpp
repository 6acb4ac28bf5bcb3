// Integrators of the beta ODE (MODEL.md s6): one interface, three schemes and a fixed-beta
// stepper. Each advances the committed state of a BetaOde to an output time exactly.
#pragma once

#include "rccm/beta_ode.hpp"
#include "rccm/config.hpp"

#include <memory>
#include <string>
#include <vector>

namespace rccm {

struct IntegratorStats {
  long steps = 0;             // accepted steps
  long rejected = 0;          // failed error tests and nonlinear solves (ARKODE)
  long rhs_evaluations = 0;   // f(t, beta) calls, each a contact solve
  long newton_iterations = 0; // ARKODE nonlinear iterations; fixed-point iterations (rate-independent)
};

/// Counts of two parts of a run (before and after a restart).
IntegratorStats operator+(const IntegratorStats& a, const IntegratorStats& b);

class AdhesionIntegrator {
 public:
  virtual ~AdhesionIntegrator() = default;
  /// Advances to exactly t_out (> the committed time); throws SolveError on failure.
  virtual void advance(double t_out) = 0;
  virtual IntegratorStats stats() const = 0;
  /// What the user must know about the result (an unstable explicit step, clamping).
  virtual std::vector<std::string> warnings() const { return {}; }
  /// The size of the last accepted step, s (a restart begins with it).
  virtual double last_step() const = 0;
  /// What the scheme has observed so far (behind its warnings), for a checkpoint, and its
  /// restoration when a run restarts from one.
  virtual std::vector<double> diagnostics() const { return {}; }
  virtual void restore(const std::vector<double>&) {}
};

/// Steps of equal size T / steps, with the output times added as step ends.
class FixedStepIntegrator : public AdhesionIntegrator {
 public:
  FixedStepIntegrator(BetaOde& ode, const Config& cfg);
  void advance(double t_out) final;
  IntegratorStats stats() const override { return stats_; }
  double last_step() const override { return last_step_; }

 protected:
  /// One step from the committed state to t_new; must end with ode_.accept(t_new, beta).
  virtual void step(double t_new) = 0;
  BetaOde& ode_;
  IntegratorStats stats_;

 private:
  std::vector<double> grid_;
  double last_step_ = 0;
};

std::unique_ptr<AdhesionIntegrator> make_integrator(BetaOde& ode, const Config& cfg);

}  // namespace rccm
