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
    // A prescribed displacement's force is the support's reaction (also where an earlier load
    // holds its DOFs alike); an applied load's is what it applies (a share on a supported DOF included).
    const Eigen::VectorXd& f = lc.reaction ? b.f_ext : Eigen::VectorXd(lc.amplitude(s.t) * lc.force);
    double F = 0, u = 0;
    for (std::size_t k = 0; k < lc.dofs.size(); ++k) F += lc.along[k] * f[lc.dofs[k]], u += lc.along[k] * b.u[lc.dofs[k]];
    b.force.push_back(F);
    b.displacement.push_back(u / double(lc.nodes));
  }
  return b;
}

}  // namespace rccm
