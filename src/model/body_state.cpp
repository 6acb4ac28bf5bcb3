#include "rccm/model/body_state.hpp"

namespace rccm {

Eigen::VectorXd adhesive_forces(const Model& model, const InterfaceState& s) {
  const Interface& I = model.interface();
  Eigen::VectorXd Radh(s.u.size());
  for (int i = 0; i < I.size(); ++i)
    I.layout.local(Radh, i) = I.law(i).adhesive_force(I.pairs[i].measure, s.beta[i], I.layout.local(s.u, i));
  return Radh;
}

namespace {

/// What both kinds share: the time, the interface force and the loads' values.
BodyState interface_side(const Model& model, const InterfaceState& s) {
  BodyState b;
  b.t = s.t;
  b.r = s.Rbar + adhesive_forces(model, s);  // r = Rbar + Radh, docs/MODEL.md s3
  for (const LoadCase& lc : model.loads()) b.value.push_back(lc.amplitude(s.t));
  return b;
}

}  // namespace

BodyState body_state(const Model& model, const InterfaceState& s) {
  BodyState b = interface_side(model, s);
  b.u = model.condensation().displacement(s.t, s.y);
  const Eigen::VectorXd Ku = model.stiffness() * b.u;
  b.f_ext = Ku - model.interface().P.transpose() * b.r;  // K u = f + P^T r (docs/MODEL.md s1)
  b.strain_energy = 0.5 * b.u.dot(Ku);
  const std::vector<char>& free = model.free_dofs();
  const Eigen::Index n = Eigen::Index(model.loads().size());
  b.work = {model.condensation().amplitudes(s.t), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (Eigen::Index k = 0; k < n; ++k) {
    const LoadCase& lc = model.loads()[k];
    // A prescribed displacement's force is the support's reaction (also where an earlier load
    // holds its DOFs alike); an applied load's is what it applies (a share on a supported DOF included).
    const Eigen::VectorXd& f = lc.reaction ? b.f_ext : Eigen::VectorXd(lc.amplitude(s.t) * lc.force);
    const Eigen::VectorXd along = lc.direction(b.u.size());
    b.force.push_back(along.dot(f));
    b.displacement.push_back(along.dot(b.u) / double(lc.nodes));
    b.work.phi[k] = 0;
    for (Eigen::Index d = 0; d < b.u.size(); ++d)
      if (free[d]) b.work.phi[k] += lc.force[d] * b.u[d];
    b.work.rho[k] = lc.displacement.dot(b.f_ext);
  }
  const Mesh& mesh = model.mesh();
  for (int node : model.probes())
    for (int c = 0; c < mesh.dim; ++c) b.probes.push_back(b.u[mesh.dof(node, c)]);
  return b;
}

BodyState body_resultants(const Model& model, const InterfaceState& s) {
  BodyState b = interface_side(model, s);
  BodyResultants f = model.body_forms().evaluate(s.t, s.y, b.r);
  b.force = std::move(f.force);
  b.displacement = std::move(f.displacement);
  b.probes = std::move(f.probes);
  b.work = std::move(f.work);
  b.strain_energy = 0.5 * (dot(b.work, b.work) + s.u.dot(b.r));  // 1/2 u.K u = 1/2 (f_ext.u + u_c.r)
  return b;
}

}  // namespace rccm
