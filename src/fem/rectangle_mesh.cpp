#include "rccm/fem/rectangle_mesh.hpp"

#include "rccm/fem/mesh_source.hpp"

#include <algorithm>
#include <cmath>

namespace rccm {

const std::vector<std::string>& rectangle_set_names() {
  static const std::vector<std::string> names = {"left",     "right",     "bottom",       "top", "bottom_left",
                                                 "bottom_right", "top_left", "top_right", "all"};
  return names;
}

Mesh make_rectangle(const MeshParams& p) {
  Mesh m;
  m.dim = 2;
  const int nx = p.nx, ny = p.ny;
  const double hx = p.size[0] / nx, hy = p.size[1] / ny;
  auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.nodes.emplace_back(p.origin[0] + i * hx, p.origin[1] + j * hy, 0.0);

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

  m.body_names = {"body"};
  m.cell_body.assign(m.cells.size(), 0);
  for (int i = 0; i < nx; ++i) {
    m.facets.push_back({id(i, 0), id(i + 1, 0)});
    m.facets.push_back({id(i, ny), id(i + 1, ny)});
  }
  for (int j = 0; j < ny; ++j) {
    m.facets.push_back({id(0, j), id(0, j + 1)});
    m.facets.push_back({id(nx, j), id(nx, j + 1)});
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
  for (int n = 0; n < m.num_nodes(); ++n) s["all"].push_back(n);

  add_box_sets(m, p.node_sets);
  place(m, p);
  return m;
}

}  // namespace rccm
