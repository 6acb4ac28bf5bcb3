// The energy balance of a run (docs/MODEL.md s3):
//   work of the external loads = bulk strain energy + change of interface free energy
//                                + damage dissipation + friction dissipation.
// The strain and free energies are functions of the state; the work and the dissipations are
// integrals int X dY along the run (f_ext . du, G dbeta, -Rbar_t . du_t), summed over the
// accepted steps: with the state halfway through each step (an adaptive run,
// BetaOde::track_midpoints) by the Stieltjes form of Simpson's rule, exact for X and Y
// quadratic in time, else by the trapezoid rule. Exact for the continuous problem; a
// time-discrete run violates it by an amount that shrinks with the step.
#pragma once

#include "rccm/model/body_state.hpp"
#include "rccm/model/interface_state.hpp"
#include "rccm/model/model.hpp"

namespace rccm {

struct EnergyTerms {
  double external_work = 0;         // int f_ext . du, N mm (loads on at t = 0: from the energy they store there)
  double strain_energy = 0;         // 1/2 u^T K u
  double free_energy_change = 0;    // sum a_i (psi_i(t) - psi_i(beta0, u = 0)), psi = 1/2 beta^2 C u^2 - w beta
  double damage_dissipation = 0;    // sum a_i int G dbeta  (= alpha beta'^2 dt >= 0)
  double friction_dissipation = 0;  // sum -int Rbar_t . du_t >= 0
  double normal_contact_work = 0;   // sum int Rbar_n du_n (0 by Signorini; reported, not balanced)
  /// An energy below this is round-off: sqrt(eps) of the interface's adhesion energy sum a_i w_i
  /// (the scale of relative_error() in a run that loads nothing).
  double round_off = 0;

  double imbalance() const {
    return external_work - (strain_energy + free_energy_change + damage_dissipation + friction_dissipation);
  }
  /// |imbalance| relative to the largest term (at least round_off).
  double relative_error() const;
};

class EnergyBalance {
 public:
  /// `rate_independent`: beta moves only on the threshold G = 0, where the law dissipates
  /// nothing; what a jump of beta releases is the balance's remainder (released in
  /// snap-through), not a damage dissipation.
  EnergyBalance(const Model& model, const InterfaceState& initial, const BodyState& initial_body,
                bool rate_independent = false);

  /// Adds the step from the previous accepted state to this one (s, b), through the state
  /// halfway (mid, mid_body) when given.
  void add(const InterfaceState& s, const BodyState& b, const InterfaceState* mid = nullptr,
           const BodyState* mid_body = nullptr);
  /// Takes up the balance at a checkpoint: `terms` accumulated up to the state (s, b).
  void resume(const InterfaceState& s, const BodyState& b, const EnergyTerms& terms);
  const EnergyTerms& terms() const { return terms_; }

 private:
  double free_energy(const InterfaceState& s) const;
  double round_off() const;
  const Model& model_;
  bool rate_independent_;
  double psi0_;
  InterfaceState previous_;
  BodyState previous_body_;
  EnergyTerms terms_;
};

}  // namespace rccm
