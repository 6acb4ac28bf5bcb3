// The rate-independent limit alpha -> 0 (docs/MODEL.md s3):
//   beta_{n+1} = min(beta_n, w / (Cn u_n^2 + Ct u_t^2)) with u from the contact solve at
//   (t_{n+1}, beta_{n+1}), made consistent by a fixed point in each step, started from beta_n.
//   A node's update may turn back: for a few iterations in a snap-through cascade (the layer
//   bends as the front jumps), where the plain iteration converges; and for good where, with
//   friction, a lower beta sticks and strains less (mubar = mu (1 - beta) grows) and the plain
//   iteration cycles. A node's updates are relaxed from its third turn that did not halve the
//   update on, by a factor halved at each such turn (node by node: a front unzipping elsewhere
//   keeps full steps). The fixed point cannot resolve beta below the contact solve's own
//   accuracy: its tolerance is at least 100 times the solver's.
#pragma once

#include "rccm/time/integrator.hpp"

#include <algorithm>

namespace rccm {

class RateIndependentIntegrator final : public FixedStepIntegrator {
 public:
  RateIndependentIntegrator(BetaSystem& ode, std::vector<double> grid, const IntegratorParams& p,
                            double solver_tolerance)
      : FixedStepIntegrator(ode, std::move(grid)),
        tolerance_(std::max(p.fixed_point_tolerance, 100 * solver_tolerance)),
        max_iterations_(p.fixed_point_iterations) {}

 private:
  void step(double t_new) override;
  double tolerance_;
  int max_iterations_;
};

}  // namespace rccm
