#include "rccm/time/energy_balance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rccm {

namespace {

double dot(double a, double b) { return a * b; }
template <class A, class B>
double dot(const A& a, const B& b) {
  return a.dot(b);
}

/// int X dY over a step, from X and Y at its start, middle and end: exact for X and Y
/// quadratic in time (Simpson's rule for X dY/dt); without the middle, the trapezoid rule.
template <class V>
double stieltjes(const V& x0, const V* xm, const V& x1, const V& y0, const V* ym, const V& y1) {
  if (!xm) return 0.5 * dot(x0 + x1, y1 - y0);
  return dot(x0, -y0 / 2 + 2 * *ym / 3 - y1 / 6) + dot(*xm, 2 * (y1 - y0) / 3) + dot(x1, y0 / 6 - 2 * *ym / 3 + y1 / 2);
}

}  // namespace

double EnergyTerms::relative_error() const {
  const double scale = std::max({std::abs(external_work), std::abs(strain_energy), std::abs(free_energy_change),
                                 std::abs(damage_dissipation), std::abs(friction_dissipation), round_off, 1e-300});
  return std::abs(imbalance()) / scale;
}

EnergyBalance::EnergyBalance(const Model& model, const InterfaceState& initial, const BodyState& initial_body,
                             bool rate_independent)
    : model_(model), rate_independent_(rate_independent), previous_(initial), previous_body_(initial_body) {
  // The free energy from the unloaded interface at beta0 (psi = -w beta0), and the work of loads
  // already on at t = 0 as what they store reaching that state elastically.
  InterfaceState unloaded = initial;
  unloaded.u.setZero();
  psi0_ = free_energy(unloaded);
  terms_.strain_energy = initial_body.strain_energy;
  terms_.free_energy_change = free_energy(initial) - psi0_;
  terms_.external_work = terms_.strain_energy + terms_.free_energy_change;
  terms_.round_off = round_off();
}

double EnergyBalance::round_off() const {
  const Interface& I = model_.interface();
  double adhesion = 0;
  for (int i = 0; i < I.size(); ++i) adhesion += I.pairs[i].measure * I.law(i).w;
  return std::sqrt(std::numeric_limits<double>::epsilon()) * adhesion;
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
  terms_.round_off = round_off();
}

void EnergyBalance::add(const InterfaceState& s, const BodyState& b, const InterfaceState* mid,
                        const BodyState* mid_body) {
  const Interface& I = model_.interface();
  const Layout& L = I.layout;
  const InterfaceState& o = previous_;
  const BodyState& ob = previous_body_;
  // f_ext . du from the loads' work pairs (LoadWork): the same sums as over the full vectors.
  const LoadWork* mid_work = mid_body ? &mid_body->work : nullptr;
  terms_.external_work += stieltjes<LoadWork>(ob.work, mid_work, b.work, ob.work, mid_work, b.work);
  terms_.strain_energy = b.strain_energy;
  terms_.free_energy_change = free_energy(s) - psi0_;
  // Pair i's components [first, first + n) of a stacked vector.
  const auto part = [](const Eigen::VectorXd& v, Eigen::Index first, Eigen::Index n) {
    return Eigen::VectorXd(v.segment(first, n));
  };
  for (int i = 0; i < I.size(); ++i) {
    const RccmLaw& law = I.law(i);
    const double G0 = law.thermodynamic_force(o.beta[i], L.local(o.u, i)),
                 G1 = law.thermodynamic_force(s.beta[i], L.local(s.u, i)),
                 Gm = mid ? law.thermodynamic_force(mid->beta[i], L.local(mid->u, i)) : 0.0;
    if (!rate_independent_)
      terms_.damage_dissipation += I.pairs[i].measure * stieltjes(G0, mid ? &Gm : nullptr, G1, o.beta[i],
                                                                  mid ? &mid->beta[i] : nullptr, s.beta[i]);
    for (const bool normal : {false, true}) {
      const Eigen::Index first = normal ? L.normal(i) : L.offset(i), n = normal ? 1 : L.tangential_size();
      const Eigen::VectorXd Rm = mid ? part(mid->Rbar, first, n) : Eigen::VectorXd(),
                            um = mid ? part(mid->u, first, n) : Eigen::VectorXd();
      const double work = stieltjes<Eigen::VectorXd>(part(o.Rbar, first, n), mid ? &Rm : nullptr,
                                                     part(s.Rbar, first, n), part(o.u, first, n), mid ? &um : nullptr,
                                                     part(s.u, first, n));
      if (normal)
        terms_.normal_contact_work += work;  // Rbar_n du_n: 0 by Signorini
      else
        terms_.friction_dissipation -= work;  // -Rbar_t . du_t
    }
  }
  previous_ = s;
  previous_body_ = b;
}

}  // namespace rccm
