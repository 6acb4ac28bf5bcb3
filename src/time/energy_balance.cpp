#include "rccm/time/energy_balance.hpp"

#include <algorithm>
#include <cmath>

namespace rccm {

double EnergyTerms::relative_error() const {
  const double scale = std::max({std::abs(external_work), std::abs(strain_energy), std::abs(free_energy_change),
                                 damage_dissipation, friction_dissipation, 1e-300});
  return std::abs(imbalance()) / scale;
}

EnergyBalance::EnergyBalance(const Model& model, const InterfaceState& initial, const BodyState& initial_body)
    : model_(model), psi0_(free_energy(initial)), previous_(initial), previous_body_(initial_body) {
  terms_.strain_energy = 0.5 * initial_body.u.dot(model.stiffness() * initial_body.u);
}

double EnergyBalance::free_energy(const InterfaceState& s) const {
  const Interface& I = model_.interface();
  double psi = 0;
  for (int i = 0; i < I.size(); ++i)
    psi += I.pairs[i].measure * I.law(i).free_energy(s.beta[i], I.layout.local(s.u, i));
  return psi;
}

void EnergyBalance::resume(const InterfaceState& s, const BodyState& b, const EnergyTerms& terms) {
  previous_ = s;
  previous_body_ = b;
  terms_ = terms;
}

void EnergyBalance::add(const InterfaceState& s, const BodyState& b) {
  const Interface& I = model_.interface();
  const Layout& L = I.layout;
  const InterfaceState& o = previous_;
  terms_.external_work += 0.5 * (previous_body_.f_ext + b.f_ext).dot(b.u - previous_body_.u);
  terms_.strain_energy = 0.5 * b.u.dot(model_.stiffness() * b.u);
  terms_.free_energy_change = free_energy(s) - psi0_;
  for (int i = 0; i < I.size(); ++i) {
    const RccmLaw& law = I.law(i);
    const double G_old = law.thermodynamic_force(o.beta[i], L.local(o.u, i));
    const double G_new = law.thermodynamic_force(s.beta[i], L.local(s.u, i));
    terms_.damage_dissipation += I.pairs[i].measure * 0.5 * (G_old + G_new) * (s.beta[i] - o.beta[i]);
    const Eigen::Index n = L.normal(i);
    terms_.friction_dissipation -=
        0.5 * (L.tangential(o.Rbar, i) + L.tangential(s.Rbar, i)).dot(L.tangential(s.u, i) - L.tangential(o.u, i));
    terms_.normal_contact_work += 0.5 * (o.Rbar[n] + s.Rbar[n]) * (s.u[n] - o.u[n]);
  }
  previous_ = s;
  previous_body_ = b;
}

}  // namespace rccm
