#include "rccm/fem/box_mesh.hpp"

#include "rccm/fem/mesh_source.hpp"

namespace rccm {

Mesh make_box(const MeshParams& p) {
  Mesh m;
  m.dim = 3;
  const int nx = p.nx, ny = p.ny, nz = p.nz;
  const double hx = p.size[0] / nx, hy = p.size[1] / ny, hz = p.depth / nz;
  auto id = [nx, ny](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.nodes.emplace_back(p.origin[0] + i * hx, p.origin[1] + j * hy, p.origin[2] + k * hz);

  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        m.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),  //
                           id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  m.body_names = {"body"};
  m.cell_body.assign(m.cells.size(), 0);

  // Boundary quads, counter-clockwise seen from outside (their normal a x b points out).
  for (int j = 0; j < ny; ++j)
    for (int k = 0; k < nz; ++k) {
      m.facets.push_back({id(0, j, k), id(0, j, k + 1), id(0, j + 1, k + 1), id(0, j + 1, k)});      // x = 0
      m.facets.push_back({id(nx, j, k), id(nx, j + 1, k), id(nx, j + 1, k + 1), id(nx, j, k + 1)});  // x = Lx
    }
  for (int i = 0; i < nx; ++i)
    for (int k = 0; k < nz; ++k) {
      m.facets.push_back({id(i, 0, k), id(i + 1, 0, k), id(i + 1, 0, k + 1), id(i, 0, k + 1)});      // y = 0
      m.facets.push_back({id(i, ny, k), id(i, ny, k + 1), id(i + 1, ny, k + 1), id(i + 1, ny, k)});  // y = Ly
    }
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      m.facets.push_back({id(i, j, 0), id(i, j + 1, 0), id(i + 1, j + 1, 0), id(i + 1, j, 0)});      // z = 0
      m.facets.push_back({id(i, j, nz), id(i + 1, j, nz), id(i + 1, j + 1, nz), id(i, j + 1, nz)});  // z = Lz
    }

  auto& s = m.node_sets;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const int n = id(i, j, k);
        if (i == 0) s["left"].push_back(n);
        if (i == nx) s["right"].push_back(n);
        if (j == 0) s["bottom"].push_back(n);
        if (j == ny) s["top"].push_back(n);
        if (k == 0) s["back"].push_back(n);
        if (k == nz) s["front"].push_back(n);
        if (j == 0 && i == 0) s["bottom_left"].push_back(n);
        if (j == 0 && i == nx) s["bottom_right"].push_back(n);
        if (j == ny && i == 0) s["top_left"].push_back(n);
        if (j == ny && i == nx) s["top_right"].push_back(n);
        if ((i == 0 || i == nx) && (j == 0 || j == ny) && (k == 0 || k == nz))  // a vertex: "top_left_back"
          s[std::string(j == 0 ? "bottom" : "top") + (i == 0 ? "_left" : "_right") + (k == 0 ? "_back" : "_front")] = {n};
        s["all"].push_back(n);
      }
  add_box_sets(m, p.node_sets);
  place(m, p);
  return m;
}

}  // namespace rccm
