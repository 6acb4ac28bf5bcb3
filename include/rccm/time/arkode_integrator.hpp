// beta integrated by SUNDIALS ARKODE (ARKStep), adaptive (docs/MODEL.md s6). Every stage
// evaluates f(t, beta) by a bipotential contact solve; after each accepted step the contact
// state is recomputed and committed (ARKStepSetPostprocessStepFn). Implicit DIRK (default:
// the ODE is stiff, its rate (Cn u_n^2 + Ct u_t^2)/alpha grows without bound as alpha -> 0)
// with modified Newton on the diagonal Jacobian, solved by KLU; or explicit ERK.
// Under mpirun with several processes ARKODE's state is distributed: each process holds a
// contiguous slice of the contact pairs (NVECTOR_PARALLEL), gathers the whole beta for each
// contact solve (replicated) and solves the diagonal Newton matrix exactly (GMRES with the
// exact inverse as preconditioner, no extra contact solve).
// A contact solve that fails inside a stage is a recoverable RHS failure: ARKODE cuts the step.
#pragma once

#include "rccm/time/integrator.hpp"

#include <memory>
#include <string>

namespace rccm {

/// Whether ARKODE knows a Butcher table of this name (implicit: a DIRK table, else ERK).
bool arkode_table_exists(bool implicit, const std::string& name);

class ArkodeIntegrator final : public BetaIntegrator {
 public:
  /// `T`: the final time (the default largest step is T / 50, the smallest 1e-9 T).
  ArkodeIntegrator(BetaSystem& ode, const IntegratorParams& params, double T);
  ~ArkodeIntegrator() override;
  void advance(double t_out) override;
  IntegratorStats stats() const override;
  double last_step() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rccm
