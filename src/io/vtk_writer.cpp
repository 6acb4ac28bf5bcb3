#include "rccm/io/vtk_writer.hpp"

#include "rccm/fem/elasticity.hpp"
#include "rccm/io/vtk_file.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

namespace rccm {

namespace {

std::string frame_name(std::size_t k) {
  char name[16];
  std::snprintf(name, sizeof name, "%04zu", k);
  return name;
}

/// The components of a symmetric tensor of VTK's 9-component layout (xx, xy, xz, yx, ..., zz)
/// from the plane (xx, yy, xy) values and zz.
void push_tensor(std::vector<double>& out, double xx, double yy, double xy, double zz) {
  out.insert(out.end(), {xx, xy, 0.0, xy, yy, 0.0, 0.0, 0.0, zz});
}

/// VTK's cell type of a linear cell of dimension `dim` with `nodes` nodes.
int cell_type(int dim, std::size_t nodes) {
  if (dim == 1) return 3;                   // VTK_LINE
  if (dim == 2) return nodes == 3 ? 5 : 9;  // VTK_TRIANGLE, VTK_QUAD
  return nodes == 4 ? 10 : 12;              // VTK_TETRA, VTK_HEXAHEDRON
}

const std::vector<std::string> tensor_components = {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"};

}  // namespace

void VtkWriter::write_bodies(const std::string& file, const BodyState& b) const {
  const Mesh& mesh = model_.mesh();
  VtkFile vtu(VtkFile::Kind::UnstructuredGrid);
  std::vector<double> xyz, u;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    xyz.insert(xyz.end(), mesh.nodes[n].data(), mesh.nodes[n].data() + 3);
    for (int c = 0; c < 3; ++c) u.push_back(c < mesh.dim ? b.u[mesh.dof(n, c)] : 0.0);
  }
  vtu.points(xyz);
  std::vector<int> types;
  for (const auto& cell : mesh.cells) types.push_back(cell_type(mesh.dim, cell.size()));
  vtu.cells(mesh.cells, types);
  vtu.point_data(VtkFile::floats("displacement", 3, u, {"x", "y", "z"}));
  // The out-of-plane components from each body's material (Material::complete): eps_zz = 0
  // and sigma_zz from the law in plane strain, sigma_zz = 0 in plane stress, the hoop
  // components axisymmetric. Shear as tensor components (gamma / 2).
  const CellFields f = cell_fields(mesh, model_.materials(), b.u);
  std::vector<double> strain_t, stress_t, von_mises;
  std::vector<std::int64_t> body(mesh.cell_body.begin(), mesh.cell_body.end());
  for (Eigen::Index c = 0; c < f.strain.cols() && mesh.dim == 3; ++c) {  // Voigt3: xx, yy, zz, yz, xz, xy
    const Voigt3 e = f.strain.col(c), s = f.stress.col(c);
    strain_t.insert(strain_t.end(), {e[0], e[5] / 2, e[4] / 2, e[5] / 2, e[1], e[3] / 2, e[4] / 2, e[3] / 2, e[2]});
    stress_t.insert(stress_t.end(), {s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2]});
    const double a = s[0] - s[1], d = s[1] - s[2], g = s[2] - s[0];
    von_mises.push_back(std::sqrt(0.5 * (a * a + d * d + g * g) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
  }
  for (Eigen::Index c = 0; c < f.strain.cols() && mesh.dim == 2; ++c) {
    const Voigt eps = f.strain.col(c), sigma = f.stress.col(c);
    push_tensor(strain_t, eps[0], eps[1], 0.5 * eps[2], eps[3]);
    push_tensor(stress_t, sigma[0], sigma[1], sigma[2], sigma[3]);
    const double a = sigma[0] - sigma[1], d = sigma[1] - sigma[3], e = sigma[3] - sigma[0];
    von_mises.push_back(std::sqrt(0.5 * (a * a + d * d + e * e) + 3 * sigma[2] * sigma[2]));
  }
  vtu.cell_data(VtkFile::integers("body", "Int32", body));  // an index in the report's list of bodies
  vtu.cell_data(VtkFile::floats("strain", 9, strain_t, tensor_components));
  vtu.cell_data(VtkFile::floats("stress", 9, stress_t, tensor_components));
  vtu.cell_data(VtkFile::floats("von_Mises", 1, von_mises));
  vtu.write(file);
}

void VtkWriter::write_interface(const std::string& file, const InterfaceState& s, const BodyState& b) const {
  const Mesh& mesh = model_.mesh();
  const Interface& I = model_.interface();
  const Layout& L = I.layout;
  VtkFile vtp(mesh.dim == 3 ? VtkFile::Kind::PolySurface : VtkFile::Kind::PolyData);
  std::vector<double> xyz;
  std::vector<int> pair_of_node(mesh.num_nodes(), -1), nodes;
  for (int i = 0; i < I.size(); ++i) {
    const int n = I.pairs[i].node;
    xyz.insert(xyz.end(), mesh.nodes[n].data(), mesh.nodes[n].data() + 3);
    if (pair_of_node[n] < 0) pair_of_node[n] = i;
    nodes.push_back(n);
  }
  vtp.points(xyz);
  std::vector<std::vector<int>> facets;  // 2D: lines, 3D: triangles and quads, of the interface's facets
  for (const auto& f : I.facets) {
    facets.emplace_back();
    for (int n : f) facets.back().push_back(pair_of_node[n]);
  }
  std::vector<int> types;
  for (const auto& f : facets) types.push_back(cell_type(mesh.dim - 1, f.size()));
  vtp.cells(facets, types);
  // Local components: tangential first, normal last, named.
  const std::vector<std::string> local = L.dim == 2 ? std::vector<std::string>{"t", "n"}
                                                    : std::vector<std::string>{"t1", "t2", "n"};
  const Eigen::VectorXd Radh = b.r - s.Rbar;
  std::vector<double> beta, a, p, u_xyz, r_xyz;
  std::vector<std::int64_t> status;
  for (int i = 0; i < I.size(); ++i) {
    beta.push_back(s.beta[i]);
    a.push_back(I.pairs[i].measure);
    status.push_back(static_cast<int>(s.status[i]));
    Eigen::Vector3d ug = Eigen::Vector3d::Zero(), rg = Eigen::Vector3d::Zero();
    for (int k = 0; k < L.dim; ++k) {
      p.push_back(b.r[L.offset(i) + k] / I.pairs[i].measure);
      ug += s.u[L.offset(i) + k] * I.pairs[i].frame.axis(k, L.dim);
      rg += b.r[L.offset(i) + k] * I.pairs[i].frame.axis(k, L.dim);
    }
    u_xyz.insert(u_xyz.end(), ug.data(), ug.data() + 3);
    r_xyz.insert(r_xyz.end(), rg.data(), rg.data() + 3);
  }
  const auto stacked = [](const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); };
  vtp.point_data(VtkFile::floats("beta", 1, beta));
  vtp.point_data(VtkFile::integers("status", "Int32", status));  // 0 separated, 1 stick, 2 slide
  vtp.point_data(VtkFile::floats("tributary", 1, a));
  vtp.point_data(VtkFile::floats("u", L.dim, stacked(s.u), local));
  vtp.point_data(VtkFile::floats("Rbar", L.dim, stacked(s.Rbar), local));
  vtp.point_data(VtkFile::floats("Radh", L.dim, stacked(Radh), local));
  vtp.point_data(VtkFile::floats("r", L.dim, stacked(b.r), local));
  vtp.point_data(VtkFile::floats("p", L.dim, p, local));
  vtp.point_data(VtkFile::floats("u_xyz", 3, u_xyz, {"x", "y", "z"}));
  vtp.point_data(VtkFile::floats("r_xyz", 3, r_xyz, {"x", "y", "z"}));
  vtp.write(file);
}

void VtkWriter::write(const InterfaceState& s, const BodyState& b) {
  if (!frames_.empty() && frames_.back().first == s.t) return;
  const std::string k = frame_name(frames_.size());
  write_bodies(directory_ + "/mesh_" + k + ".vtu", b);
  write_interface(directory_ + "/interface_" + k + ".vtp", s, b);
  frames_.emplace_back(s.t, k);
  write_collections();
}

void VtkWriter::write_collections() const {
  std::vector<std::pair<double, std::string>> bodies, interface;
  for (const auto& [t, name] : frames_) {
    bodies.emplace_back(t, "mesh_" + name + ".vtu");
    interface.emplace_back(t, "interface_" + name + ".vtp");
  }
  write_collection(directory_ + "/results.pvd", bodies);
  write_collection(directory_ + "/interface.pvd", interface);
}

void VtkWriter::resume(double t, bool frame_at_t) {
  // The frames the earlier run listed (our own results.pvd: one DataSet line each).
  std::ifstream in(directory_ + "/results.pvd");
  const std::regex entry("timestep=\"([^\"]*)\" file=\"mesh_([0-9]+)\\.vtu\"");
  const double tolerance = 1e-9 * std::max(1.0, std::abs(t));
  std::smatch m;
  std::vector<std::pair<double, std::string>> kept;
  for (std::string line; std::getline(in, line);) {
    if (!std::regex_search(line, m, entry)) continue;
    const double frame_t = std::stod(m[1]);
    if (frame_t < t - tolerance || (frame_at_t && frame_t <= t + tolerance)) kept.emplace_back(frame_t, m[2]);
  }
  frames_ = kept;
  for (std::size_t k = frames_.size();; ++k) {
    const std::string vtu = directory_ + "/mesh_" + frame_name(k) + ".vtu", vtp = directory_ + "/interface_" + frame_name(k) + ".vtp";
    if (!std::filesystem::exists(vtu) && !std::filesystem::exists(vtp)) break;
    std::filesystem::remove(vtu);
    std::filesystem::remove(vtp);
  }
  write_collections();
}

}  // namespace rccm
