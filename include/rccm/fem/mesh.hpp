// A mesh: nodes, cells, boundary facets and named node sets, in 2D or 3D. It comes from a
// mesh source (the built-in rectangle of rectangle_mesh.hpp, or a file) and enters the
// Model from outside.
#pragma once

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace rccm {

/// A point or vector in a message: (x, y), or (x, y, z) on a 3D mesh.
std::string point(const Eigen::Vector3d& x, int dim);

/// Where points given in the mesh source's own frame (node-set boxes, watch points) lie in
/// the global frame of the mesh: x -> origin + rotation (x - origin).
struct Placement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return origin + rotation * (x - origin); }
};

/// A boundary facet of a node set (2D: an edge a-b), with its outward unit normal and the
/// consistent weights int N_a dS, int N_b dS of its end nodes (dS = ds, or 2 pi r ds on an
/// axisymmetric mesh).
struct BoundaryEdge {
  int a = -1, b = -1;
  Eigen::Vector3d outward = Eigen::Vector3d::Zero();
  double weight_a = 0, weight_b = 0;  // mm (axisymmetric: mm^2)
  double length = 0;                  // mm
};

/// A boundary facet of a 3D node set (a triangle or a quad, counter-clockwise seen from
/// outside), with its outward unit normal, its area and the consistent weights int N_a dA of
/// its nodes.
struct BoundaryFace {
  std::vector<int> nodes;
  Eigen::Vector3d outward = Eigen::Vector3d::Zero();
  std::vector<double> weights;  // mm^2
  double area = 0;              // mm^2
};

struct Mesh {
  int dim = 2;
  bool axisymmetric = false;                     // a meridian section (x = r >= 0, y = z): measures carry 2 pi r
  std::vector<Eigen::Vector3d> nodes;            // mm; z = 0 in 2D
  std::vector<std::vector<int>> cells;           // node lists: T3, Q4 counter-clockwise in 2D; T4, H8 of positive volume in 3D
  std::vector<int> cell_body;                    // body of each cell: an index in body_names
  std::vector<std::string> body_names;           // the bodies (physical surfaces of a gmsh file; "body" for the rectangle)
  std::vector<std::vector<int>> facets;          // boundary facets (edges in 2D; triangles or quads counter-clockwise seen from outside in 3D), each of one cell only
  std::map<std::string, std::vector<int>> node_sets;
  // The elements of a node set read from a gmsh physical curve (2D) or surface (3D), each as
  // its sorted node list, sorted: the only boundary facets that set loads or bonds (a facet
  // joining two of its parts is not one of them).
  std::map<std::string, std::vector<std::vector<int>>> set_elements;
  Placement placement;
  std::string source;                            // the file it was read from, for messages ("" for the rectangle)

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  /// Degrees of freedom: `dim` per node, dof(n, c) = dim n + c.
  int num_dofs() const { return dim * num_nodes(); }
  int dof(int node, int component) const { return dim * node + component; }

  /// The nodes of a named set; throws InputError naming the nearest known set.
  const std::vector<int>& node_set(const std::string& name) const;
  std::vector<std::string> node_set_names() const;

  /// Boundary facets whose nodes all belong to `set`.
  std::vector<std::vector<int>> facets_within(const std::vector<int>& set) const;

  /// The boundary facets of the named node set: for a set read from a gmsh physical curve
  /// (2D) or surface (3D), those among its own elements; for any other, facets_within.
  std::vector<std::vector<int>> facets_of(const std::string& name) const;

  /// The boundary edges `facets` (2D), with their outward normals and nodal weights.
  std::vector<BoundaryEdge> boundary_edges(const std::vector<std::vector<int>>& facets) const;

  /// The boundary triangles and quads `facets` (3D), with their outward normals and nodal weights.
  std::vector<BoundaryFace> boundary_faces(const std::vector<std::vector<int>>& facets) const;

  /// Unit outward normal of the boundary per node of `set`: the average of its `facets`',
  /// weighted by their measure; zero for a node on none.
  std::vector<Eigen::Vector3d> outward_normals(const std::vector<int>& set, const std::vector<std::vector<int>>& facets) const;

  /// Consistent (= lumped, for linear edges) measure per node of `set`: int N_i dS over its
  /// `facets`, mm (axisymmetric: mm^2, the area of the ring; 3D: mm^2); 0 on none.
  std::vector<double> tributary_measures(const std::vector<int>& set, const std::vector<std::vector<int>>& facets) const;

  /// Half the length of each adjacent edge of `facets` per node of `set`, mm (in the plane of
  /// the mesh); in 3D the tributary area, mm^2 (what a debonded measure sums).
  std::vector<double> tributary_lengths(const std::vector<int>& set, const std::vector<std::vector<int>>& facets) const;

  /// The cells that hold `x`, on their boundary too (to 1e-9 of the cell's size).
  std::vector<int> cells_holding(const Eigen::Vector3d& x) const;

  /// The bodies (indices in body_names) with a cell that holds `x`: one where x is inside a
  /// body, two on the boundary two share.
  std::vector<int> bodies_holding(const Eigen::Vector3d& x) const;
};

}  // namespace rccm
