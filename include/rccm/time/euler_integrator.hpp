// The paper's explicit scheme (docs/MODEL.md s6, paper step 3.4), fixed steps:
//   f at t_{n+1} with beta_n; beta_{n+1} = clamp(beta_n + dt f, 0, beta_n);
//   the state at (t_{n+1}, beta_{n+1}) accepted.
// Stable only while dt |df/dbeta| = dt (Cn u_n^2 + Ct u_t^2) / alpha < 2: beyond, the clamp
// hides a blow-up, and the run says so (warnings()).
#pragma once

#include "rccm/time/integrator.hpp"

namespace rccm {

class EulerIntegrator final : public FixedStepIntegrator {
 public:
  using FixedStepIntegrator::FixedStepIntegrator;
  std::vector<std::string> warnings() const override;
  std::vector<double> diagnostics() const override { return {max_ratio_, double(clamped_)}; }
  void restore(const std::vector<double>& d) override;

 private:
  void step(double t_new) override;
  void take_step(double t_new);
  double max_ratio_ = 0;  // max of dt |df/dbeta|
  long clamped_ = 0;      // node-steps clamped at beta = 0
};

}  // namespace rccm
