#include "rccm/fem/mesh_source.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/fem/box_mesh.hpp"
#include "rccm/fem/gmsh_mesh.hpp"
#include "rccm/fem/rectangle_mesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace rccm {

Mesh make_mesh(const Config& cfg) {
  if (cfg.mesh.file.empty()) return cfg.mesh.dim() == 3 ? make_box(cfg.mesh) : make_rectangle(cfg.mesh);
  Mesh m = read_gmsh(cfg.mesh, cfg.where("mesh.file"));
  try {
    add_box_sets(m, cfg.mesh.node_sets);
  } catch (const InputError& e) {
    throw InputError(cfg.where("mesh.node_sets") + ": " + e.what());
  }
  place(m, cfg.mesh);
  return m;
}

void add_box_sets(Mesh& mesh, const std::vector<NodeSetDef>& boxes) {
  if (boxes.empty()) return;
  Eigen::Vector3d lo = mesh.nodes.front(), hi = lo;
  for (const Eigen::Vector3d& x : mesh.nodes) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double tol = 1e-9 * (hi - lo).maxCoeff();
  for (const NodeSetDef& d : boxes) {
    if (mesh.node_sets.count(d.name)) throw InputError("'" + d.name + "' names a node set of the mesh already");
    std::vector<int> nodes;
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      const Eigen::Vector3d& x = mesh.nodes[n];
      const bool in_z = d.box.size() < 6 || (x[2] >= d.box[4] - tol && x[2] <= d.box[5] + tol);
      if (x[0] >= d.box[0] - tol && x[0] <= d.box[1] + tol && x[1] >= d.box[2] - tol && x[1] <= d.box[3] + tol && in_z)
        nodes.push_back(n);
    }
    mesh.node_sets[d.name] = nodes;
  }
}

void place(Mesh& mesh, const MeshParams& p) {
  mesh.placement.origin = Eigen::Vector3d(p.origin[0], p.origin[1], p.origin[2]);
  const Eigen::Vector3d axis(p.axis[0], p.axis[1], p.axis[2]);
  mesh.placement.rotation = Eigen::AngleAxisd(p.rotation * M_PI / 180.0, axis).toRotationMatrix();
  if (p.rotation != 0.0)
    for (Eigen::Vector3d& x : mesh.nodes) x = mesh.placement(x);
}

}  // namespace rccm
