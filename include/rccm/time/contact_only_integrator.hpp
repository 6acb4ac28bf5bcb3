// beta held at its committed value: contact steps only (the pure Signorini-Coulomb problem
// with beta0 = 0, or a bonded interface that may not damage).
#pragma once

#include "rccm/time/integrator.hpp"

namespace rccm {

class ContactOnlyIntegrator final : public FixedStepIntegrator {
 public:
  using FixedStepIntegrator::FixedStepIntegrator;

 private:
  void step(double t_new) override;
};

}  // namespace rccm
