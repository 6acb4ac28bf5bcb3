// The rate-independent limit alpha -> 0 (MODEL.md s3):
//   beta_{n+1} = min(beta_n, w / (Cn u_n^2 + Ct u_t^2)) with u from the contact solve at
//   (t_{n+1}, beta_{n+1}), made consistent by a fixed point in each step. Starting from
//   beta_n the iterates decrease monotonically to the largest consistent beta.
#pragma once

#include "rccm/adhesion_integrator.hpp"

namespace rccm {

class RateIndependentIntegrator final : public FixedStepIntegrator {
 public:
  RateIndependentIntegrator(BetaOde& ode, const Config& cfg);

 private:
  void step(double t_new) override;
  double w_, tolerance_;
  int max_iterations_;
};

}  // namespace rccm
