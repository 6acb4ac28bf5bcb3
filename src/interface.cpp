#include "rccm/interface.hpp"

#include "rccm/errors.hpp"

namespace rccm {

Interface make_interface(const Mesh& mesh, const InterfaceParams& p) {
  Interface I;
  I.nodes = mesh.node_set(p.boundary);
  const std::vector<double> a = mesh.tributary_lengths(I.nodes);
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] <= 0)
      throw InputError("node set '" + p.boundary +
                       "' must be a chain of boundary edges (node " + std::to_string(I.nodes[i]) +
                       " lies on none of its edges)");
  if (I.nodes.empty())
    throw InputError("node set '" + p.boundary + "' has no nodes");
  I.a = Eigen::Map<const Eigen::VectorXd>(a.data(), static_cast<Eigen::Index>(a.size()));
  I.n = Eigen::Vector2d(p.normal[0], p.normal[1]).normalized();
  I.t = Eigen::Vector2d(I.n.y(), -I.n.x());
  I.Cn = p.Cn;
  I.Ct = p.Ct;
  std::vector<Eigen::Triplet<double>> trip;
  for (int i = 0; i < I.size(); ++i)
    for (int c = 0; c < 2; ++c) {
      trip.emplace_back(2 * i, 2 * I.nodes[i] + c, I.t[c]);
      trip.emplace_back(2 * i + 1, 2 * I.nodes[i] + c, I.n[c]);
    }
  I.P.resize(2 * I.size(), 2 * static_cast<int>(mesh.nodes.size()));
  I.P.setFromTriplets(trip.begin(), trip.end());
  return I;
}

SparseMatrix Interface::initial_springs() const {
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(size());
  return springs(one, one);
}

SparseMatrix Interface::springs(const Eigen::VectorXd& weight_t, const Eigen::VectorXd& weight_n) const {
  Eigen::VectorXd d(2 * size());
  for (int i = 0; i < size(); ++i) d.segment<2>(2 * i) << a[i] * Ct * weight_t[i], a[i] * Cn * weight_n[i];
  return SparseMatrix(P.transpose() * d.asDiagonal() * P);
}

}  // namespace rccm
