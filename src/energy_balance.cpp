#include "rccm/energy_balance.hpp"

#include <algorithm>
#include <cmath>

namespace rccm {

double EnergyTerms::relative_error() const {
  const double scale = std::max({std::abs(external_work), std::abs(strain_energy), std::abs(free_energy_change),
                                 damage_dissipation, friction_dissipation, 1e-300});
  return std::abs(imbalance()) / scale;
}

EnergyBalance::EnergyBalance(const Model& model, const InterfaceState& initial, const BodyState& initial_body)
    : model_(model), previous_(initial), previous_body_(initial_body) {
  psi0_ = free_energy(initial);
  terms_.strain_energy = 0.5 * initial_body.u.dot(model.stiffness() * initial_body.u);
}

double EnergyBalance::free_energy(const InterfaceState& s) const {
  const Interface& I = model_.interface();
  const double w = model_.config().interface.w;
  double psi = 0;
  for (int i = 0; i < I.size(); ++i) psi += I.a[i] * rccm::free_energy(s.beta[i], s.u.segment<2>(2 * i), I.Ct, I.Cn, w);
  return psi;
}

void EnergyBalance::resume(const InterfaceState& s, const BodyState& b, const EnergyTerms& terms) {
  previous_ = s;
  previous_body_ = b;
  terms_ = terms;
}

void EnergyBalance::add(const InterfaceState& s, const BodyState& b) {
  const Interface& I = model_.interface();
  const double w = model_.config().interface.w;
  const InterfaceState& o = previous_;
  terms_.external_work += 0.5 * (previous_body_.f_ext + b.f_ext).dot(b.u - previous_body_.u);
  terms_.strain_energy = 0.5 * b.u.dot(model_.stiffness() * b.u);
  terms_.free_energy_change = free_energy(s) - psi0_;
  for (int i = 0; i < I.size(); ++i) {
    const double G_old = thermodynamic_force(o.beta[i], o.u.segment<2>(2 * i), I.Ct, I.Cn, w);
    const double G_new = thermodynamic_force(s.beta[i], s.u.segment<2>(2 * i), I.Ct, I.Cn, w);
    terms_.damage_dissipation += I.a[i] * 0.5 * (G_old + G_new) * (s.beta[i] - o.beta[i]);
    terms_.friction_dissipation -= 0.5 * (o.Rbar[2 * i] + s.Rbar[2 * i]) * (s.u[2 * i] - o.u[2 * i]);
    terms_.normal_contact_work += 0.5 * (o.Rbar[2 * i + 1] + s.Rbar[2 * i + 1]) * (s.u[2 * i + 1] - o.u[2 * i + 1]);
  }
  previous_ = s;
  previous_body_ = b;
}

}  // namespace rccm
