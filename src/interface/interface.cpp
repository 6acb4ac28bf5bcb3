#include "rccm/interface/interface.hpp"

#include "rccm/base/errors.hpp"

#include <sstream>

namespace rccm {

namespace {

RccmLaw law_of(const InterfaceParams& p) { return {p.Cn, p.Ct, p.w, p.alpha, p.mu}; }

/// Value k of a config list of one value or one per contact node.
double per_node(const Config& cfg, const InterfaceParams& p, const char* setting, const std::vector<double>& v,
                std::size_t nodes, std::size_t k) {
  if (v.size() != 1 && v.size() != nodes)
    throw InputError(cfg.where(p.path + "." + setting) + ": give one value or one per contact node (" +
                     std::to_string(nodes) + "), got " + std::to_string(v.size()));
  return v.size() == 1 ? v[0] : v[k];
}

}  // namespace

Interface make_interface(const Mesh& mesh, const Config& cfg) {
  Interface I;
  I.layout.dim = mesh.dim;
  for (const InterfaceParams& p : cfg.interfaces) {
    const std::string where = cfg.where(p.path + ".boundary") + ": ";
    std::vector<int> nodes;
    try {
      nodes = mesh.node_set(p.boundary);
    } catch (const InputError& e) {
      throw InputError(where + e.what());
    }
    if (nodes.empty()) throw InputError(where + "node set '" + p.boundary + "' has no nodes");
    const std::vector<double> a = mesh.tributary_measures(nodes);
    const std::vector<Eigen::Vector3d> outward = mesh.outward_normals(nodes);
    const FlatFoundation foundation{Eigen::Vector3d(p.normal[0], p.normal[1], 0.0).normalized()};
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (a[k] <= 0)
        throw InputError(where + "node set '" + p.boundary + "' must be a chain of boundary edges (node " +
                         std::to_string(nodes[k]) + " lies on none of its edges)");
      // The foundation's normal points into the body: against the boundary's outward normal
      // (within 60 degrees), not out of the body nor along the interface.
      if (-foundation.normal.dot(outward[k]) < 0.5) {
        const Eigen::Vector3d& x = mesh.nodes[nodes[k]];
        std::ostringstream m;
        m << cfg.where(p.path + ".normal") << ": the foundation normal (" << foundation.normal.x() << ", "
          << foundation.normal.y() << ") does not point into the body at contact node " << k << " (" << x.x() << ", "
          << x.y() << "), where the boundary's inward normal is (" << 0.0 - outward[k].x() << ", " << 0.0 - outward[k].y()
          << "); give the normal from the foundation into the body";
        throw InputError(m.str());
      }
      ContactPair c;
      c.node = nodes[k];
      c.measure = a[k];
      c.g0 = per_node(cfg, p, "g0", p.g0, nodes.size(), k);
      c.beta0 = per_node(cfg, p, "beta0", p.beta0, nodes.size(), k);
      c.frame = foundation.frame_at(mesh.nodes[c.node]);
      c.law = static_cast<int>(I.laws.size());
      I.pairs.push_back(c);
    }
    I.laws.push_back(law_of(p));
  }
  const int dim = I.layout.dim;
  std::vector<Eigen::Triplet<double>> trip;
  for (int i = 0; i < I.size(); ++i) {
    const ContactPair& c = I.pairs[i];
    for (int k = 0; k < dim; ++k)
      for (int x = 0; x < dim; ++x) {
        const double axis = c.frame.axis(k, dim)[x];
        trip.emplace_back(I.layout.offset(i) + k, mesh.dof(c.node, x), axis);
        if (c.opposite >= 0) trip.emplace_back(I.layout.offset(i) + k, mesh.dof(c.opposite, x), -axis);
      }
  }
  I.P.resize(dim * I.size(), mesh.num_dofs());
  I.P.setFromTriplets(trip.begin(), trip.end());
  return I;
}

Eigen::VectorXd Interface::spring_stiffness() const {
  Eigen::VectorXd D(layout.offset(size()));
  for (int i = 0; i < size(); ++i) layout.local(D, i) = law(i).spring(pairs[i].measure, layout.dim);
  return D;
}

SparseMatrix Interface::springs(const Eigen::VectorXd& weight_t, const Eigen::VectorXd& weight_n) const {
  Eigen::VectorXd d(layout.offset(size()));
  for (int i = 0; i < size(); ++i) {
    const double a = pairs[i].measure;
    layout.tangential(d, i).setConstant(a * law(i).Ct * weight_t[i]);
    d[layout.normal(i)] = a * law(i).Cn * weight_n[i];
  }
  return SparseMatrix(P.transpose() * d.asDiagonal() * P);
}

SparseMatrix Interface::initial_springs() const {
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(size());
  return springs(one, one);
}

}  // namespace rccm
