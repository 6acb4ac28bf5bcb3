#include "rccm/fem/loads.hpp"

#include "rccm/base/errors.hpp"

#include <algorithm>
#include <cmath>

namespace rccm {

namespace {

/// Whether two piecewise linear amplitudes (constant beyond their ends) are the same function:
/// equal, to round-off of their largest value, at every breakpoint of either, hence everywhere.
bool same_function(const TimeFunction& a, const TimeFunction& b) {
  double scale = 0;
  for (const TimeFunction* f : {&a, &b})
    for (double v : f->v) scale = std::max(scale, std::abs(v));
  const auto agree = [&](double t) { return std::abs(a(t) - b(t)) <= 1e-12 * scale; };
  return std::all_of(a.t.begin(), a.t.end(), agree) && std::all_of(b.t.begin(), b.t.end(), agree);
}

}  // namespace

std::vector<LoadCase> make_load_cases(const Mesh& mesh, const Config& cfg, const std::vector<int>& axis) {
  const int ndof = mesh.num_dofs();
  constexpr int on_axis = -2;  // owner of the axis's u_r = 0
  std::vector<int> owner(ndof, -1);
  for (int dof : axis) owner[dof] = on_axis;
  std::vector<LoadCase> out;
  for (std::size_t k = 0; k < cfg.loads.size(); ++k) {
    const LoadParams& p = cfg.loads[k];
    const std::string where = cfg.where(p.path + ".node_set") + ": ";
    const std::vector<int>* set = nullptr;
    std::vector<std::vector<int>> facets;  // the set's boundary facets: where a traction or pressure acts
    try {
      set = &mesh.node_set(p.node_set);
      facets = mesh.facets_of(p.node_set);
    } catch (const InputError& e) {
      throw InputError(where + e.what());
    }
    if (set->empty()) throw InputError(where + "node set '" + p.node_set + "' has no nodes");
    LoadCase lc{p.amplitude, Eigen::VectorXd::Zero(ndof), Eigen::VectorXd::Zero(ndof), {}, {}, {}, 0,
                p.kind == LoadKind::Displacement};
    lc.nodes = static_cast<int>(set->size());
    if (p.kind == LoadKind::Pressure) {
      const std::vector<Eigen::Vector3d> outward = mesh.outward_normals(*set, facets);
      for (std::size_t i = 0; i < set->size(); ++i)
        for (int x = 0; x < mesh.dim; ++x) lc.dofs.push_back(mesh.dof((*set)[i], x)), lc.along.push_back(-outward[i][x]);
    } else {
      for (int n : *set) lc.dofs.push_back(mesh.dof(n, p.component)), lc.along.push_back(1.0);
    }
    if (p.kind == LoadKind::Displacement) {
      const bool zero = std::all_of(p.amplitude.v.begin(), p.amplitude.v.end(), [](double v) { return v == 0.0; });
      for (int dof : lc.dofs) {
        if (owner[dof] == on_axis && zero) continue;  // u_r = 0 again: the axis holds it already
        if (owner[dof] == on_axis)
          throw InputError(where + "node " + std::to_string(dof / mesh.dim) +
                           " lies on the axis (r = 0), where an axisymmetric model holds u_r = 0: a radial displacement "
                           "there would open a hole at the axis; start the node set's box at r > 0, or prescribe y only");
        if (owner[dof] >= 0) {
          // Two sets meeting at a corner, each held there alike (left x = 0, bottom x = 0): held once.
          if (same_function(out[owner[dof]].amplitude, p.amplitude)) continue;
          throw InputError(where + "node " + std::to_string(dof / mesh.dim) + " component " + "xyz"[p.component] +
                           " is already prescribed by loads.[" + std::to_string(owner[dof]) + "] to other values: a "
                           "node holds one displacement; take it out of one of the node sets (a box node set, "
                           "mesh.node_sets), or give both loads the same value or table");
        }
        owner[dof] = static_cast<int>(k);
        lc.displacement[dof] = 1.0;
        lc.prescribed.push_back(dof);
      }
    } else if (p.kind == LoadKind::Force) {
      for (int dof : lc.dofs) lc.force[dof] = 1.0;  // axisymmetric: on the whole ring
    } else {  // consistent nodal forces of a unit traction along a component, or a unit pressure along -outward
      const auto unit_load = [&](const Eigen::Vector3d& outward, int x) {
        return p.kind == LoadKind::Pressure ? -outward[x] : double(x == p.component);
      };
      if (facets.empty())
        throw InputError(where + "node set '" + p.node_set + "' has no boundary " + (mesh.dim == 3 ? "face" : "edge") +
                         " to carry a " + (p.kind == LoadKind::Pressure ? "pressure" : "traction"));
      if (mesh.dim == 3) {  // the set's boundary triangles and quads
        for (const BoundaryFace& f : mesh.boundary_faces(facets))
          for (std::size_t a = 0; a < f.nodes.size(); ++a)
            for (int x = 0; x < 3; ++x) lc.force[mesh.dof(f.nodes[a], x)] += unit_load(f.outward, x) * f.weights[a];
      } else {
        for (const BoundaryEdge& e : mesh.boundary_edges(facets))
          for (int x = 0; x < 2; ++x) {
            lc.force[mesh.dof(e.a, x)] += unit_load(e.outward, x) * e.weight_a;
            lc.force[mesh.dof(e.b, x)] += unit_load(e.outward, x) * e.weight_b;
          }
      }
    }
    out.push_back(std::move(lc));
  }
  // A force on a prescribed DOF would act on the support, not on the body: refused. A
  // distributed load may end on a support (its share there goes into the support), but not
  // lie on supports only.
  for (std::size_t k = 0; k < out.size(); ++k) {
    const LoadParams& p = cfg.loads[k];
    if (p.kind == LoadKind::Displacement) continue;
    const auto supported = [&](int dof) { return owner[dof] != -1; };
    const auto first = std::find_if(out[k].dofs.begin(), out[k].dofs.end(), supported);
    if (p.kind == LoadKind::Force && first != out[k].dofs.end())
      throw InputError(cfg.where(p.path + ".node_set") + ": node " + std::to_string(*first / mesh.dim) + " component " +
                       "xyz"[*first % mesh.dim] + " is prescribed by " +
                       (owner[*first] == on_axis
                            ? std::string("the axis (r = 0, where an axisymmetric model holds u_r = 0): a force there acts "
                                          "on the axis, not on the body; start the node set's box at r > 0")
                            : "loads.[" + std::to_string(owner[*first]) +
                                  "]: a force there acts on the support, not on the body; load another node set, or drop "
                                  "one of the two loads"));
    if (std::all_of(out[k].dofs.begin(), out[k].dofs.end(), supported))
      throw InputError(cfg.where(p.path + ".node_set") + ": every node of '" + p.node_set + "' is prescribed along the " +
                       (p.kind == LoadKind::Pressure ? "pressure" : "traction") + ": it would act on the supports only");
  }
  return out;
}

Eigen::VectorXd LoadCase::direction(Eigen::Index ndof) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(ndof);
  for (std::size_t j = 0; j < dofs.size(); ++j) v[dofs[j]] += along[j];
  return v;
}

std::vector<int> prescribed_dofs(const std::vector<LoadCase>& loads) {
  std::vector<int> dofs;
  for (const LoadCase& lc : loads) dofs.insert(dofs.end(), lc.prescribed.begin(), lc.prescribed.end());
  return dofs;
}

}  // namespace rccm
