#include "rccm/body_state.hpp"

namespace rccm {

BodyState body_state(const Model& model, const InterfaceState& s) {
  BodyState b;
  b.t = s.t;
  b.u = model.condensation().displacement(s.t, s.y);
  const Interface& I = model.interface();
  b.r = s.Rbar;
  for (int i = 0; i < I.size(); ++i)  // r = Rbar + Radh, MODEL.md s3
    b.r.segment<2>(2 * i) += adhesive_force(I.a[i], s.beta[i], I.Ct, I.Cn, s.u.segment<2>(2 * i));
  b.f_ext = model.stiffness() * b.u - I.P.transpose() * b.r;  // K u = f + P^T r (MODEL.md s1)
  for (const LoadCase& lc : model.loads()) {
    b.value.push_back(lc.amplitude(s.t));
    const Eigen::VectorXd& where = lc.prescribed.empty() ? lc.force : lc.displacement;
    double F = 0;
    for (Eigen::Index d = 0; d < where.size(); ++d)
      if (where[d] != 0) F += b.f_ext[d];
    b.force.push_back(F);
  }
  return b;
}

}  // namespace rccm
