// The paper's explicit scheme (MODEL.md s6, paper step 3.4), fixed steps:
//   contact at t_{n+1} with beta_n; beta_{n+1} = clamp(beta_n + dt f, 0, beta_n);
//   re-solve the contact at (t_{n+1}, beta_{n+1}) and commit.
// Stable only while dt (Cn u_n^2 + Ct u_t^2) / alpha < 2: beyond, the clamp hides a blow-up,
// and the run says so (warnings()).
#pragma once

#include "rccm/adhesion_integrator.hpp"

namespace rccm {

class EulerIntegrator final : public FixedStepIntegrator {
 public:
  EulerIntegrator(BetaOde& ode, const Config& cfg);
  std::vector<std::string> warnings() const override;
  std::vector<double> diagnostics() const override { return {max_ratio_, double(clamped_)}; }
  void restore(const std::vector<double>& d) override;

  double max_stability_ratio() const { return max_ratio_; }  // max of dt (C u^2) / alpha
  long clamped() const { return clamped_; }                  // node-steps clamped at beta = 0

 private:
  void step(double t_new) override;
  void take_step(double t_new);
  double alpha_;
  double max_ratio_ = 0;
  long clamped_ = 0;
};

}  // namespace rccm
