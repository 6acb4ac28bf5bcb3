#include "rccm/fem/mesh.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/suggest.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace rccm {

std::string point(const Eigen::Vector3d& x, int dim) {
  std::ostringstream m;
  m << "(" << x.x() + 0.0 << ", " << x.y() + 0.0;  // + 0.0: -0 written as 0
  if (dim == 3) m << ", " << x.z() + 0.0;
  m << ")";
  return m.str();
}

std::vector<std::string> Mesh::node_set_names() const {
  std::vector<std::string> names;
  for (const auto& [name, nodes] : node_sets) names.push_back(name);
  return names;
}

const std::vector<int>& Mesh::node_set(const std::string& name) const {
  const auto it = node_sets.find(name);
  if (it != node_sets.end()) return it->second;
  throw InputError("no node set named '" + name + "'" + (source.empty() ? "" : " in " + source) +
                   suggestion(name, node_set_names()));
}

std::vector<std::vector<int>> Mesh::facets_within(const std::vector<int>& set) const {
  std::vector<char> in(nodes.size(), 0);
  for (int n : set) in[n] = 1;
  std::vector<std::vector<int>> out;
  for (const auto& f : facets)
    if (std::all_of(f.begin(), f.end(), [&](int n) { return in[n] != 0; })) out.push_back(f);
  return out;
}

std::vector<std::vector<int>> Mesh::facets_of(const std::string& name) const {
  std::vector<std::vector<int>> out = facets_within(node_set(name));
  const auto own = set_elements.find(name);
  if (own == set_elements.end()) return out;
  out.erase(std::remove_if(out.begin(), out.end(), [&](std::vector<int> f) {
              std::sort(f.begin(), f.end());
              return !std::binary_search(own->second.begin(), own->second.end(), f);
            }), out.end());
  return out;
}

std::vector<BoundaryEdge> Mesh::boundary_edges(const std::vector<std::vector<int>>& facets) const {
  RCCM_VERIFY(dim == 2, "boundary edges (2D)");
  std::vector<char> in(nodes.size(), 0);
  for (const auto& f : facets)
    for (int n : f) in[n] = 1;
  // The cell centre behind each cell edge with both nodes on the facets.
  std::map<std::pair<int, int>, Eigen::Vector3d> centre_of_edge;
  for (const auto& cell : cells) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int n : cell) centre += nodes[n] / double(cell.size());
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const int a = cell[k], b = cell[(k + 1) % cell.size()];
      if (in[a] && in[b]) centre_of_edge[{std::min(a, b), std::max(a, b)}] = centre;
    }
  }
  std::vector<BoundaryEdge> out;
  for (const auto& f : facets) {
    BoundaryEdge e;
    e.a = f[0], e.b = f[1];
    const Eigen::Vector3d t = nodes[e.b] - nodes[e.a];
    e.length = t.norm();
    e.outward = Eigen::Vector3d(t.y(), -t.x(), 0.0) / e.length;
    const auto centre = centre_of_edge.find({std::min(e.a, e.b), std::max(e.a, e.b)});
    RCCM_VERIFY(centre != centre_of_edge.end(), "a boundary facet is an edge of a cell");
    if (e.outward.dot(0.5 * (nodes[e.a] + nodes[e.b]) - centre->second) < 0) e.outward = -e.outward;
    if (axisymmetric) {  // int N_a 2 pi r ds with r linear along the edge
      const double ra = nodes[e.a].x(), rb = nodes[e.b].x();
      e.weight_a = 2 * M_PI * e.length * (2 * ra + rb) / 6;
      e.weight_b = 2 * M_PI * e.length * (ra + 2 * rb) / 6;
    } else {
      e.weight_a = e.weight_b = 0.5 * e.length;
    }
    out.push_back(e);
  }
  return out;
}

std::vector<BoundaryFace> Mesh::boundary_faces(const std::vector<std::vector<int>>& facets) const {
  RCCM_VERIFY(dim == 3, "boundary faces (3D)");
  std::vector<BoundaryFace> out;
  for (const auto& f : facets) {
    RCCM_VERIFY(f.size() == 3 || f.size() == 4, "a 3D boundary facet is a triangle or a quad");
    BoundaryFace face;
    face.nodes = f;
    face.weights.assign(f.size(), 0.0);
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    if (f.size() == 3) {  // a flat triangle: int N_a dA = A / 3
      normal = (nodes[f[1]] - nodes[f[0]]).cross(nodes[f[2]] - nodes[f[0]]);
      face.area = 0.5 * normal.norm();
      face.weights.assign(3, face.area / 3);
    } else {  // the bilinear quad x(xi, eta) by 2 x 2 Gauss points: dA = |x_xi x x_eta|
      const double g = 1.0 / std::sqrt(3.0);
      const double xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1};
      for (int q = 0; q < 4; ++q) {
        const double s = g * xi[q], t = g * eta[q];
        Eigen::Vector3d dxi = Eigen::Vector3d::Zero(), deta = Eigen::Vector3d::Zero();
        for (int a = 0; a < 4; ++a) {
          dxi += 0.25 * xi[a] * (1 + eta[a] * t) * nodes[f[a]];
          deta += 0.25 * eta[a] * (1 + xi[a] * s) * nodes[f[a]];
        }
        const Eigen::Vector3d n = dxi.cross(deta);
        for (int a = 0; a < 4; ++a) face.weights[a] += 0.25 * (1 + xi[a] * s) * (1 + eta[a] * t) * n.norm();
        face.area += n.norm();
        normal += n;
      }
    }
    face.outward = normal.normalized();
    out.push_back(face);
  }
  return out;
}

std::vector<Eigen::Vector3d> Mesh::outward_normals(const std::vector<int>& set,
                                                   const std::vector<std::vector<int>>& facets) const {
  std::vector<Eigen::Vector3d> sum(nodes.size(), Eigen::Vector3d::Zero());
  if (dim == 3)
    for (const BoundaryFace& f : boundary_faces(facets))
      for (int n : f.nodes) sum[n] += f.area * f.outward;
  else
    for (const BoundaryEdge& e : boundary_edges(facets)) {
      sum[e.a] += e.length * e.outward;
      sum[e.b] += e.length * e.outward;
    }
  std::vector<Eigen::Vector3d> out;
  for (int n : set) out.push_back(sum[n].norm() > 0 ? Eigen::Vector3d(sum[n].normalized()) : Eigen::Vector3d::Zero());
  return out;
}

std::vector<double> Mesh::tributary_measures(const std::vector<int>& set,
                                             const std::vector<std::vector<int>>& facets) const {
  std::vector<double> a(nodes.size(), 0.0);
  if (dim == 3)
    for (const BoundaryFace& f : boundary_faces(facets))
      for (std::size_t k = 0; k < f.nodes.size(); ++k) a[f.nodes[k]] += f.weights[k];
  else
    for (const BoundaryEdge& e : boundary_edges(facets)) a[e.a] += e.weight_a, a[e.b] += e.weight_b;
  std::vector<double> out;
  for (int n : set) out.push_back(a[n]);
  return out;
}

std::vector<double> Mesh::tributary_lengths(const std::vector<int>& set,
                                            const std::vector<std::vector<int>>& facets) const {
  if (dim == 3) return tributary_measures(set, facets);
  std::vector<double> a(nodes.size(), 0.0);
  for (const BoundaryEdge& e : boundary_edges(facets)) a[e.a] += 0.5 * e.length, a[e.b] += 0.5 * e.length;
  std::vector<double> out;
  for (int n : set) out.push_back(a[n]);
  return out;
}

namespace {

/// Whether the simplex of `corners` (a triangle in 2D, a tetrahedron in 3D) holds x: its
/// barycentric coordinates all >= -tolerance. A flat simplex (a Q4 or H8 split where corners
/// line up) holds nothing: its volume is the cell's elsewhere.
bool simplex_holds(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& x, double tolerance) {
  const int dim = static_cast<int>(corners.size()) - 1;
  Eigen::MatrixXd A(dim, dim);
  for (int j = 0; j < dim; ++j) A.col(j) = (corners[j + 1] - corners[0]).head(dim);
  if (std::abs(A.determinant()) <= 1e-12 * std::pow(A.colwise().norm().maxCoeff(), dim)) return false;
  const Eigen::VectorXd lambda = A.fullPivLu().solve((x - corners[0]).head(dim));
  return (lambda.array() >= -tolerance).all() && lambda.sum() <= 1 + tolerance;
}

}  // namespace

std::vector<int> Mesh::cells_holding(const Eigen::Vector3d& x) const {
  // Each cell as simplices of its corners: T3, T4 itself; Q4 two triangles; H8 six tetrahedra
  // about its diagonal 0-6 (straight-edged cells: what the linear elements are).
  static const std::vector<std::vector<int>> t3 = {{0, 1, 2}}, q4 = {{0, 1, 2}, {0, 2, 3}}, t4 = {{0, 1, 2, 3}};
  static const std::vector<std::vector<int>> h8 = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                                   {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  std::vector<int> holding;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::vector<int>& cell = cells[c];
    const std::vector<std::vector<int>>& simplices = cell.size() == 8 ? h8 : dim == 3 ? t4 : cell.size() == 4 ? q4 : t3;
    const auto holds = [&](const std::vector<int>& simplex) {
      std::vector<Eigen::Vector3d> corners;
      for (int k : simplex) corners.push_back(nodes[cell[k]]);
      return simplex_holds(corners, x, 1e-9);
    };
    if (std::any_of(simplices.begin(), simplices.end(), holds)) holding.push_back(static_cast<int>(c));
  }
  return holding;
}

std::vector<int> Mesh::bodies_holding(const Eigen::Vector3d& x) const {
  std::vector<int> bodies;
  for (int c : cells_holding(x))
    if (std::find(bodies.begin(), bodies.end(), cell_body[c]) == bodies.end()) bodies.push_back(cell_body[c]);
  return bodies;
}

}  // namespace rccm
