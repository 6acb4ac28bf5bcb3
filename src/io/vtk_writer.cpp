#include "rccm/io/vtk_writer.hpp"

#include "rccm/io/atomic_file.hpp"
#include "rccm/fem/elasticity.hpp"
#include "rccm/base/errors.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace rccm {

namespace {

/// Von Mises stress of a plane state; sigma_zz = nu (sigma_xx + sigma_yy) in plane strain.
double von_mises(const Eigen::Vector3d& s, double szz) {
  const double a = s[0] - s[1], b = s[1] - szz, c = szz - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3 * s[2] * s[2]);
}

void data_array(std::ostream& out, const char* name, int components, const Eigen::MatrixXd& values) {
  out << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"" << components
      << "\" format=\"ascii\">\n";
  char buf[32];
  for (Eigen::Index j = 0; j < values.cols(); ++j) {
    for (Eigen::Index c = 0; c < values.rows(); ++c) {
      std::snprintf(buf, sizeof buf, "%.10g ", values(c, j));
      out << buf;
    }
    out << "\n";
  }
  out << "</DataArray>\n";
}

}  // namespace

void VtkWriter::write(const InterfaceState& s, const BodyState& b) {
  const Mesh& mesh = model_.mesh();
  const Interface& I = model_.interface();
  const Layout& L = I.layout;
  const MaterialParams& mat = model_.material();
  const Eigen::Index nn = static_cast<Eigen::Index>(mesh.nodes.size()), nc = static_cast<Eigen::Index>(mesh.cells.size());

  Eigen::MatrixXd X(3, nn), U = Eigen::MatrixXd::Zero(3, nn);
  for (Eigen::Index n = 0; n < nn; ++n) {
    X.col(n) = mesh.nodes[n];
    for (int c = 0; c < mesh.dim; ++c) U(c, n) = b.u[mesh.dof(int(n), c)];
  }
  // Interface data on the contact nodes, zero elsewhere (with a mask field).
  Eigen::MatrixXd contact = Eigen::MatrixXd::Zero(1, nn), beta = Eigen::MatrixXd::Zero(1, nn),
                  status = Eigen::MatrixXd::Zero(1, nn), Rbar = Eigen::MatrixXd::Zero(L.dim, nn),
                  r = Eigen::MatrixXd::Zero(L.dim, nn);
  for (int i = 0; i < I.size(); ++i) {
    const int n = I.pairs[i].node;
    contact(0, n) = 1;
    beta(0, n) = s.beta[i];
    status(0, n) = static_cast<int>(s.status[i]);
    Rbar.col(n) = L.local(s.Rbar, i);
    r.col(n) = L.local(b.r, i);
  }
  const Eigen::Matrix3Xd eps = cell_strains(mesh, b.u);
  const Eigen::Matrix3Xd sigma = hooke_matrix(mat) * eps;
  Eigen::MatrixXd vm(1, nc);
  for (Eigen::Index c = 0; c < nc; ++c)
    vm(0, c) = von_mises(sigma.col(c), mat.hypothesis == Hypothesis::PlaneStrain ? mat.nu * (sigma(0, c) + sigma(1, c)) : 0.0);

  const std::string name = file_name(files_.size());
  const std::string path = directory_ + "/" + name;
  AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << nn << "\" NumberOfCells=\"" << nc << "\">\n<Points>\n";
  data_array(out, "coordinates [mm]", 3, X);
  out << "</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& cell : mesh.cells) {
    for (int n : cell) out << n << " ";
    out << "\n";
  }
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for (const auto& cell : mesh.cells) out << (offset += cell.size()) << " ";
  out << "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (const auto& cell : mesh.cells) out << (cell.size() == 3 ? 5 : 9) << " ";  // VTK_TRIANGLE, VTK_QUAD
  out << "\n</DataArray>\n</Cells>\n<PointData Vectors=\"displacement [mm]\">\n";
  data_array(out, "displacement [mm]", 3, U);
  data_array(out, "contact node", 1, contact);
  data_array(out, "beta", 1, beta);
  data_array(out, "status (0 separated, 1 stick, 2 slide)", 1, status);
  data_array(out, "Rbar (t, n) [N]", L.dim, Rbar);
  data_array(out, "r = Rbar + Radh (t, n) [N]", L.dim, r);
  out << "</PointData>\n<CellData>\n";
  data_array(out, "strain (xx, yy, xy)", 3, eps);
  data_array(out, "stress (xx, yy, xy) [MPa]", 3, sigma);
  data_array(out, "von Mises [MPa]", 1, vm);
  out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  file.commit();

  files_.emplace_back(s.t, name);
  write_collection();
}

std::string VtkWriter::file_name(std::size_t k) {
  char name[64];
  std::snprintf(name, sizeof name, "mesh_%04zu.vtu", k);
  return name;
}

void VtkWriter::write_collection() const {
  AtomicFile collection(directory_ + "/results.pvd");
  std::ostream& pvd = collection.stream();
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, file] : files_) pvd << "<DataSet timestep=\"" << t << "\" file=\"" << file << "\"/>\n";
  pvd << "</Collection>\n</VTKFile>\n";
  collection.commit();
}

void VtkWriter::resume(const std::vector<double>& times) {
  files_.clear();
  for (double t : times) files_.emplace_back(t, file_name(files_.size()));
  for (std::size_t k = files_.size(); std::filesystem::exists(directory_ + "/" + file_name(k)); ++k)
    std::filesystem::remove(directory_ + "/" + file_name(k));
  write_collection();
}

}  // namespace rccm
