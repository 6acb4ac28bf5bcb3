// A mesh: nodes, cells, boundary facets and named node sets, in 2D or 3D. It comes from a
// mesh source (the built-in rectangle of rectangle_mesh.hpp, or a file) and enters the
// Model from outside.
#pragma once

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace rccm {

/// Where points given in the mesh source's own frame (node-set boxes, watch points) lie in
/// the global frame of the mesh: x -> origin + rotation (x - origin).
struct Placement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return origin + rotation * (x - origin); }
};

struct Mesh {
  int dim = 2;
  std::vector<Eigen::Vector3d> nodes;            // mm; z = 0 in 2D
  std::vector<std::vector<int>> cells;           // node lists, counter-clockwise in 2D
  std::vector<std::vector<int>> facets;          // boundary facets (edges in 2D), each of one cell only
  std::map<std::string, std::vector<int>> node_sets;
  Placement placement;

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  /// Degrees of freedom: `dim` per node, dof(n, c) = dim n + c.
  int num_dofs() const { return dim * num_nodes(); }
  int dof(int node, int component) const { return dim * node + component; }

  /// The nodes of a named set; throws InputError naming the nearest known set.
  const std::vector<int>& node_set(const std::string& name) const;
  std::vector<std::string> node_set_names() const;

  /// Boundary facets whose nodes all belong to `set`.
  std::vector<std::vector<int>> facets_within(const std::vector<int>& set) const;

  /// Unit outward normal of the boundary per node of `set`: the average of its facets' in the
  /// set, weighted by their measure; zero for a node on no such facet.
  std::vector<Eigen::Vector3d> outward_normals(const std::vector<int>& set) const;

  /// Lumped facet measure per node of `set` (2D: half the length of each adjacent edge in
  /// the set), mm; 0 for a node on no such facet.
  std::vector<double> tributary_measures(const std::vector<int>& set) const;
};

}  // namespace rccm
