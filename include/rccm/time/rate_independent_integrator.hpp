// The rate-independent limit alpha -> 0 (docs/MODEL.md s3):
//   beta_{n+1} = min(beta_n, w / (Cn u_n^2 + Ct u_t^2)) with u from the contact solve at
//   (t_{n+1}, beta_{n+1}), made consistent by a fixed point in each step. Without friction,
//   starting from beta_n the iterates decrease monotonically to the largest consistent beta.
//   With friction a lower beta may stick and strain less (mubar = mu (1 - beta) grows), and
//   the plain iteration can cycle: a node whose update turned back without halving three
//   times is then relaxed, by a factor halved at each such turn (node by node: a front
//   unzipping elsewhere keeps full steps). Fewer turns come and go in a snap-through cascade,
//   with or without friction, where the plain iteration converges. The fixed point cannot resolve beta below the contact solve's own accuracy: its
//   tolerance is at least 100 times the solver's.
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
