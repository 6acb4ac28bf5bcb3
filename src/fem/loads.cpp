#include "rccm/fem/loads.hpp"

#include "rccm/base/errors.hpp"

namespace rccm {

std::vector<LoadCase> make_load_cases(const Mesh& mesh, const Config& cfg) {
  const int ndof = mesh.num_dofs();
  std::vector<int> owner(ndof, -1);
  std::vector<LoadCase> out;
  for (std::size_t k = 0; k < cfg.loads.size(); ++k) {
    const LoadParams& p = cfg.loads[k];
    const std::string where = cfg.where(p.path + ".node_set") + ": ";
    const std::vector<int>* set = nullptr;
    try {
      set = &mesh.node_set(p.node_set);
    } catch (const InputError& e) {
      throw InputError(where + e.what());
    }
    if (set->empty()) throw InputError(where + "node set '" + p.node_set + "' has no nodes");
    LoadCase lc{p.amplitude, Eigen::VectorXd::Zero(ndof), Eigen::VectorXd::Zero(ndof), {}, {}};
    for (int n : *set) lc.dofs.push_back(mesh.dof(n, p.component));
    if (p.kind == LoadKind::Displacement) {
      for (int dof : lc.dofs) {
        if (owner[dof] >= 0)
          throw InputError(where + "node " + std::to_string(dof / mesh.dim) + " component " + "xyz"[p.component] +
                           " is already prescribed by loads.[" + std::to_string(owner[dof]) + "]");
        owner[dof] = static_cast<int>(k);
        lc.displacement[dof] = 1.0;
        lc.prescribed.push_back(dof);
      }
    } else if (p.kind == LoadKind::Force) {
      for (int dof : lc.dofs) lc.force[dof] = 1.0;
    } else {
      const std::vector<double> a = mesh.tributary_measures(*set);
      double total = 0;
      for (std::size_t i = 0; i < set->size(); ++i) {
        lc.force[lc.dofs[i]] = a[i];  // lumped traction: value * a_i
        total += a[i];
      }
      if (total <= 0) throw InputError(where + "node set '" + p.node_set + "' has no boundary edge to carry a traction");
    }
    out.push_back(std::move(lc));
  }
  // A force on a prescribed DOF would act on the support, not on the body: refused.
  for (std::size_t k = 0; k < out.size(); ++k)
    if (cfg.loads[k].kind != LoadKind::Displacement)
      for (int dof : out[k].dofs)
        if (owner[dof] >= 0)
          throw InputError(cfg.where(cfg.loads[k].path + ".node_set") + ": node " + std::to_string(dof / mesh.dim) +
                           " component " + "xyz"[dof % mesh.dim] + " is prescribed by loads.[" +
                           std::to_string(owner[dof]) + "]: a force there acts on the support, not on the body; "
                           "load another node set, or drop one of the two loads");
  return out;
}

std::vector<int> prescribed_dofs(const std::vector<LoadCase>& loads) {
  std::vector<int> dofs;
  for (const LoadCase& lc : loads) dofs.insert(dofs.end(), lc.prescribed.begin(), lc.prescribed.end());
  return dofs;
}

}  // namespace rccm
