#include "rccm/model/body_state.hpp"

namespace rccm {

Eigen::VectorXd adhesive_forces(const Model& model, const InterfaceState& s) {
  const Interface& I = model.interface();
  Eigen::VectorXd Radh(s.u.size());
  for (int i = 0; i < I.size(); ++i)
    I.layout.local(Radh, i) = I.law(i).adhesive_force(I.pairs[i].measure, s.beta[i], I.layout.local(s.u, i));
  return Radh;
}

BodyState body_state(const Model& model, const InterfaceState& s) {
  BodyState b;
  b.t = s.t;
  b.u = model.condensation().displacement(s.t, s.y);
  b.r = s.Rbar + adhesive_forces(model, s);                                 // r = Rbar + Radh, docs/MODEL.md s3
  b.f_ext = model.stiffness() * b.u - model.interface().P.transpose() * b.r;  // K u = f + P^T r (docs/MODEL.md s1)
  for (const LoadCase& lc : model.loads()) {
    b.value.push_back(lc.amplitude(s.t));
    double F = 0, u = 0;
    for (int dof : lc.dofs) F += b.f_ext[dof], u += b.u[dof];
    b.force.push_back(F);
    b.displacement.push_back(u / double(lc.dofs.size()));
  }
  return b;
}

}  // namespace rccm
