#include "rccm/fem/mesh.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/suggest.hpp"

#include <algorithm>

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
