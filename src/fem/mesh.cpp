#include "rccm/fem/mesh.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/suggest.hpp"

#include <algorithm>
#include <map>

namespace rccm {

std::vector<std::string> Mesh::node_set_names() const {
  std::vector<std::string> names;
  for (const auto& [name, nodes] : node_sets) names.push_back(name);
  return names;
}

const std::vector<int>& Mesh::node_set(const std::string& name) const {
  const auto it = node_sets.find(name);
  if (it != node_sets.end()) return it->second;
  throw InputError("no node set named '" + name + "'" + suggestion(name, node_set_names()));
}

std::vector<std::vector<int>> Mesh::facets_within(const std::vector<int>& set) const {
  std::vector<char> in(nodes.size(), 0);
  for (int n : set) in[n] = 1;
  std::vector<std::vector<int>> out;
  for (const auto& f : facets)
    if (std::all_of(f.begin(), f.end(), [&](int n) { return in[n] != 0; })) out.push_back(f);
  return out;
}

std::vector<Eigen::Vector3d> Mesh::outward_normals(const std::vector<int>& set) const {
  RCCM_VERIFY(dim == 2, "outward normals of edges (2D)");
  std::vector<char> in(nodes.size(), 0);
  for (int n : set) in[n] = 1;
  // The cell centre behind each cell edge with both nodes in the set.
  std::map<std::pair<int, int>, Eigen::Vector3d> centre_of_edge;
  for (const auto& cell : cells) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int n : cell) centre += nodes[n] / double(cell.size());
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const int a = cell[k], b = cell[(k + 1) % cell.size()];
      if (in[a] && in[b]) centre_of_edge[{std::min(a, b), std::max(a, b)}] = centre;
    }
  }
  std::vector<Eigen::Vector3d> sum(nodes.size(), Eigen::Vector3d::Zero());
  for (const auto& e : facets_within(set)) {
    const Eigen::Vector3d t = nodes[e[1]] - nodes[e[0]];
    Eigen::Vector3d n(t.y(), -t.x(), 0.0);  // length |t|: weighted by the edge's length
    const auto centre = centre_of_edge.find({std::min(e[0], e[1]), std::max(e[0], e[1])});
    RCCM_VERIFY(centre != centre_of_edge.end(), "a boundary facet is an edge of a cell");
    if (n.dot(0.5 * (nodes[e[0]] + nodes[e[1]]) - centre->second) < 0) n = -n;
    sum[e[0]] += n;
    sum[e[1]] += n;
  }
  std::vector<Eigen::Vector3d> out;
  for (int n : set) out.push_back(sum[n].norm() > 0 ? Eigen::Vector3d(sum[n].normalized()) : Eigen::Vector3d::Zero());
  return out;
}

std::vector<double> Mesh::tributary_measures(const std::vector<int>& set) const {
  RCCM_VERIFY(dim == 2, "tributary measures of edges (2D)");
  std::vector<double> a(nodes.size(), 0.0);
  for (const auto& e : facets_within(set)) {
    const double half = 0.5 * (nodes[e[0]] - nodes[e[1]]).norm();
    a[e[0]] += half;
    a[e[1]] += half;
  }
  std::vector<double> out;
  for (int n : set) out.push_back(a[n]);
  return out;
}

}  // namespace rccm
