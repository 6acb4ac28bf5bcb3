#include "rccm/mesh.hpp"

#include "rccm/errors.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <array>

namespace rccm {

const std::vector<int>& Mesh::node_set(const std::string& name) const {
  const auto it = node_sets.find(name);
  if (it != node_sets.end()) return it->second;
  std::string known;
  for (const auto& [k, v] : node_sets) known += (known.empty() ? "" : ", ") + k;
  throw InputError("no node set named '" + name + "'; known sets: " + known);
}

std::vector<std::array<int, 2>> Mesh::edges_within(const std::vector<int>& set) const {
  std::vector<char> in(nodes.size(), 0);
  for (int n : set) in[n] = 1;
  std::vector<std::array<int, 2>> out;
  for (const auto& e : boundary)
    if (in[e[0]] && in[e[1]]) out.push_back(e);
  return out;
}

std::vector<double> Mesh::tributary_lengths(const std::vector<int>& set) const {
  std::vector<double> a(nodes.size(), 0.0);
  for (const auto& e : edges_within(set)) {
    const double half = 0.5 * (nodes[e[0]] - nodes[e[1]]).norm();
    a[e[0]] += half;
    a[e[1]] += half;
  }
  std::vector<double> out;
  for (int n : set) out.push_back(a[n]);
  return out;
}

Eigen::Vector2d placed(const MeshParams& p, const Eigen::Vector2d& x) {
  const Eigen::Vector2d o(p.origin[0], p.origin[1]);
  return o + Eigen::Rotation2Dd(p.rotation * M_PI / 180.0) * (x - o);
}

Mesh make_rectangle(const MeshParams& p) {
  Mesh m;
  m.element = p.element;
  const int nx = p.nx, ny = p.ny;
  const double hx = p.size[0] / nx, hy = p.size[1] / ny;
  auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.nodes.emplace_back(p.origin[0] + i * hx, p.origin[1] + j * hy);

  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (p.element == ElementType::Q4) {
        m.cells.push_back({a, b, c, d});
      } else {
        m.cells.push_back({a, b, c});
        m.cells.push_back({a, c, d});
      }
    }

  for (int i = 0; i < nx; ++i) {
    m.boundary.push_back({id(i, 0), id(i + 1, 0)});
    m.boundary.push_back({id(i, ny), id(i + 1, ny)});
  }
  for (int j = 0; j < ny; ++j) {
    m.boundary.push_back({id(0, j), id(0, j + 1)});
    m.boundary.push_back({id(nx, j), id(nx, j + 1)});
  }

  auto& s = m.node_sets;
  for (int i = 0; i <= nx; ++i) {
    s["bottom"].push_back(id(i, 0));
    s["top"].push_back(id(i, ny));
  }
  for (int j = 0; j <= ny; ++j) {
    s["left"].push_back(id(0, j));
    s["right"].push_back(id(nx, j));
  }
  s["bottom_left"] = {id(0, 0)};
  s["bottom_right"] = {id(nx, 0)};
  s["top_left"] = {id(0, ny)};
  s["top_right"] = {id(nx, ny)};
  for (int n = 0; n < static_cast<int>(m.nodes.size()); ++n) s["all"].push_back(n);

  const double tol = 1e-9 * std::max(p.size[0], p.size[1]);
  for (const NodeSetDef& d : p.node_sets) {
    std::vector<int> nodes;
    for (int n = 0; n < static_cast<int>(m.nodes.size()); ++n) {
      const Eigen::Vector2d& x = m.nodes[n];
      if (x[0] >= d.box[0] - tol && x[0] <= d.box[1] + tol && x[1] >= d.box[2] - tol &&
          x[1] <= d.box[3] + tol)
        nodes.push_back(n);
    }
    s[d.name] = nodes;
  }
  if (p.rotation != 0.0)
    for (Eigen::Vector2d& x : m.nodes) x = placed(p, x);
  return m;
}

}  // namespace rccm
