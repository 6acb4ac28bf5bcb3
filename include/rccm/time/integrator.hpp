// Integrators of the beta ODE (docs/MODEL.md s6): ARKODE (adaptive), explicit Euler (the
// paper's scheme), the rate-independent limit and contact-only steps (beta held). Each
// advances the committed state of a BetaSystem to an output time exactly.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/time/beta_system.hpp"

#include <memory>
#include <string>
#include <vector>

namespace rccm {

/// How the integrator's state is split among the processes of an mpirun run (ARKODE's, each
/// process holding a slice of the contact pairs): from `smallest` to `largest` pairs each,
/// `pairs` in all. processes = 0: not split, every process holds the whole state.
struct StateSlices {
  int processes = 0;
  int smallest = 0, largest = 0, pairs = 0;
};

struct IntegratorStats {
  long steps = 0;              // accepted steps
  long rejected = 0;           // steps tried again: failed error tests and failed stage solves (ARKODE)
  long rhs_evaluations = 0;    // f(t, beta) calls, each a contact solve
  long newton_iterations = 0;  // ARKODE nonlinear iterations; fixed-point iterations (rate-independent)
  StateSlices slices;          // of the state among the processes (ARKODE under mpirun)
};

/// Counts of two parts of a run (before and after a restart); the slices of the second.
IntegratorStats operator+(const IntegratorStats& a, const IntegratorStats& b);

class BetaIntegrator {
 public:
  virtual ~BetaIntegrator() = default;
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

/// Steps along a given grid of times (equal steps with the output times added).
class FixedStepIntegrator : public BetaIntegrator {
 public:
  FixedStepIntegrator(BetaSystem& ode, std::vector<double> grid) : ode_(ode), grid_(std::move(grid)) {}
  void advance(double t_out) final;
  IntegratorStats stats() const override { return stats_; }
  double last_step() const override { return last_step_; }

 protected:
  /// One step from the committed state to t_new; must end with ode_.accept(t_new, beta).
  virtual void step(double t_new) = 0;
  BetaSystem& ode_;
  IntegratorStats stats_;

 private:
  std::vector<double> grid_;
  double last_step_ = 0;
};

/// The accepted times of a fixed-step run: `steps` equal increments of [0, T] and the
/// output times, merged (times closer than 1e-12 T are one).
std::vector<double> time_grid(double T, int steps, const std::vector<double>& output_times);

/// The times a run stops at: the output times (0 included, the initial state), and T.
std::vector<double> stop_times(double T, const std::vector<double>& output_times);

/// The integrator of cfg.integrator.method on `ode`; `initial_step` > 0 overrides
/// integrator.initial_step (a restart begins with the step it stopped at).
std::unique_ptr<BetaIntegrator> make_integrator(BetaSystem& ode, const Config& cfg, double initial_step = 0);

}  // namespace rccm
