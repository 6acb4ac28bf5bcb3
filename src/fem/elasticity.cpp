#include "rccm/fem/elasticity.hpp"

#include "rccm/base/errors.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace rccm {

namespace {

/// Strain-displacement matrix B (4 x 2k: xx, yy, xy, zz) at (xi, eta) of a cell, and the
/// volume weight of the point: det J (per unit thickness) or 2 pi r det J (axisymmetric,
/// where eps_zz = u_r / r). T3: xi, eta are area coordinates (B constant); Q4: the
/// reference square [-1, 1]^2.
double strain_matrix(const Mesh& mesh, const std::vector<int>& cell, double xi, double eta, Eigen::MatrixXd& B) {
  const int k = static_cast<int>(cell.size());
  Eigen::MatrixXd dN(2, k);  // derivatives of the shape functions in the reference cell
  Eigen::VectorXd N(k);
  if (k == 3) {
    dN << -1, 1, 0, -1, 0, 1;
    N << 1 - xi - eta, xi, eta;
  } else {
    dN << -(1 - eta), (1 - eta), (1 + eta), -(1 + eta),  //
        -(1 - xi), -(1 + xi), (1 + xi), (1 - xi);
    dN *= 0.25;
    N << (1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta);
    N *= 0.25;
  }
  Eigen::MatrixXd X(k, 2);
  for (int a = 0; a < k; ++a) X.row(a) = mesh.nodes[cell[a]].head<2>().transpose();
  const Eigen::Matrix2d J = dN * X;
  const double det = J.determinant();
  RCCM_VERIFY(det > 0, "cell with non-positive Jacobian (clockwise or degenerate)");
  const Eigen::MatrixXd dNx = J.inverse() * dN;  // d/dx, d/dy
  B.setZero(4, 2 * k);
  for (int a = 0; a < k; ++a) {
    B(0, 2 * a) = dNx(0, a);
    B(1, 2 * a + 1) = dNx(1, a);
    B(2, 2 * a) = dNx(1, a);
    B(2, 2 * a + 1) = dNx(0, a);
  }
  if (!mesh.axisymmetric) return det;
  const double r = N.dot(X.col(0));
  for (int a = 0; a < k; ++a) B(3, 2 * a) = N[a] / r;  // eps_theta = u_r / r
  return 2 * M_PI * r * det;
}

/// 3D: strain-displacement matrix B (6 x 3k: xx, yy, zz, yz, xz, xy) at r = (xi, eta, zeta)
/// of a cell, and det J. T4 (k = 4): r are volume coordinates of the reference tetrahedron
/// (B constant); H8 (k = 8): the reference cube [-1, 1]^3.
double strain_matrix_3d(const Mesh& mesh, const std::vector<int>& cell, const Eigen::Vector3d& r, Eigen::MatrixXd& B) {
  static const double corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const int k = static_cast<int>(cell.size());
  Eigen::MatrixXd dN(3, k), X(k, 3);
  for (int a = 0; a < k; ++a) X.row(a) = mesh.nodes[cell[a]].transpose();
  if (k == 4) {  // N = 1 - xi - eta - zeta, xi, eta, zeta
    dN << -1, 1, 0, 0, -1, 0, 1, 0, -1, 0, 0, 1;
  } else {
    for (int a = 0; a < 8; ++a) {
      const double* c = corner[a];
      const Eigen::Vector3d f(1 + c[0] * r[0], 1 + c[1] * r[1], 1 + c[2] * r[2]);  // N_a = f0 f1 f2 / 8
      dN(0, a) = 0.125 * c[0] * f[1] * f[2];
      dN(1, a) = 0.125 * c[1] * f[0] * f[2];
      dN(2, a) = 0.125 * c[2] * f[0] * f[1];
    }
  }
  const Eigen::Matrix3d J = dN * X;
  const double det = J.determinant();
  RCCM_VERIFY(det > 0, "3D cell with non-positive Jacobian (inverted or degenerate)");
  const Eigen::MatrixXd d = J.inverse() * dN;  // d/dx, d/dy, d/dz
  B.setZero(6, 3 * k);
  for (int a = 0; a < k; ++a) {
    B(0, 3 * a) = d(0, a);
    B(1, 3 * a + 1) = d(1, a);
    B(2, 3 * a + 2) = d(2, a);
    B(3, 3 * a + 1) = d(2, a), B(3, 3 * a + 2) = d(1, a);  // gamma_yz
    B(4, 3 * a) = d(2, a), B(4, 3 * a + 2) = d(0, a);      // gamma_xz
    B(5, 3 * a) = d(1, a), B(5, 3 * a + 1) = d(0, a);      // gamma_xy
  }
  return det;
}

/// Quadrature points (xi, eta, zeta, weight) of a 3D cell: T4 its centroid (volume det J / 6),
/// H8 2 x 2 x 2 Gauss points.
std::vector<Eigen::Vector4d> quadrature_3d(int k) {
  if (k == 4) return {{0.25, 0.25, 0.25, 1.0 / 6}};
  const double g = 1.0 / std::sqrt(3.0);
  std::vector<Eigen::Vector4d> q;
  for (int i = 0; i < 8; ++i) q.emplace_back(i & 1 ? g : -g, i & 2 ? g : -g, i & 4 ? g : -g, 1.0);
  return q;
}

/// The point where a cell's strain and stress are reported: its centre.
Eigen::Vector3d centre_3d(int k) { return k == 4 ? Eigen::Vector3d::Constant(0.25) : Eigen::Vector3d::Zero(); }

/// Quadrature points (xi, eta, weight) of a cell: T3 1 point (3 axisymmetric: the hoop
/// term varies), Q4 2 x 2 Gauss.
std::vector<Eigen::Vector3d> quadrature(int k, bool axisymmetric) {
  if (k == 3 && !axisymmetric) return {{1.0 / 3, 1.0 / 3, 0.5}};
  if (k == 3) return {{1.0 / 6, 1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}};
  const double g = 1.0 / std::sqrt(3.0);
  return {{-g, -g, 1}, {g, -g, 1}, {g, g, 1}, {-g, g, 1}};
}

Eigen::VectorXd cell_displacement(const Mesh& mesh, const std::vector<int>& cell, const Eigen::VectorXd& u) {
  const int d = mesh.dim;
  Eigen::VectorXd ue(d * cell.size());
  for (std::size_t a = 0; a < cell.size(); ++a) ue.segment(d * a, d) = u.segment(mesh.dof(cell[a], 0), d);
  return ue;
}

/// The stiffness of cell c, K_e = int B^T D B dV at the cell's quadrature points.
Eigen::MatrixXd cell_stiffness(const Mesh& mesh, std::size_t c, const Material& material) {
  const auto& cell = mesh.cells[c];
  const int k = static_cast<int>(cell.size());
  Eigen::MatrixXd B, Ke = Eigen::MatrixXd::Zero(mesh.dim * k, mesh.dim * k);
  if (mesh.dim == 3) {
    RCCM_VERIFY(k == 4 || k == 8, "3D cells are T4 or H8");
    for (const Eigen::Vector4d& q : quadrature_3d(k)) {
      const double dV = strain_matrix_3d(mesh, cell, q.head<3>(), B);
      Ke += B.transpose() * material.D3() * B * dV * q[3];
    }
    return Ke;
  }
  for (const Eigen::Vector3d& q : quadrature(k, mesh.axisymmetric)) {
    const double dV = strain_matrix(mesh, cell, q[0], q[1], B);
    Ke += B.transpose() * material.D() * B * dV * q[2];
  }
  return Ke;
}

}  // namespace

SparseMatrix assemble_stiffness(const Mesh& mesh, const std::vector<Material>& body_materials) {
  const int d = mesh.dim;
  std::vector<Eigen::Triplet<double>> trip;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const auto& cell = mesh.cells[c];
    const Eigen::MatrixXd Ke = cell_stiffness(mesh, c, body_materials[mesh.cell_body[c]]);
    for (int a = 0; a < Ke.rows(); ++a)
      for (int b = 0; b < Ke.cols(); ++b) trip.emplace_back(mesh.dof(cell[a / d], a % d), mesh.dof(cell[b / d], b % d), Ke(a, b));
  }
  const int n = mesh.num_dofs();
  SparseMatrix K(n, n);
  K.setFromTriplets(trip.begin(), trip.end());
  return K;
}

CellFields cell_fields(const Mesh& mesh, const std::vector<Material>& body_materials, const Eigen::VectorXd& u) {
  const Eigen::Index rows = mesh.dim == 3 ? 6 : 4, cells = static_cast<Eigen::Index>(mesh.cells.size());
  CellFields f{Eigen::MatrixXd(rows, cells), Eigen::MatrixXd(rows, cells)};
  Eigen::MatrixXd B;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    if (mesh.dim == 3) {  // at the cell centre
      strain_matrix_3d(mesh, mesh.cells[c], centre_3d(static_cast<int>(mesh.cells[c].size())), B);
      const Voigt3 eps = B * cell_displacement(mesh, mesh.cells[c], u);
      f.strain.col(c) = eps;
      f.stress.col(c) = body_materials[mesh.cell_body[c]].D3() * eps;
      continue;
    }
    const auto& cell = mesh.cells[c];
    const double centre = cell.size() == 3 ? 1.0 / 3 : 0.0;
    strain_matrix(mesh, cell, centre, centre, B);
    Voigt eps = B * cell_displacement(mesh, cell, u), sigma;
    body_materials[mesh.cell_body[c]].complete(eps, sigma);
    f.strain.col(c) = eps;
    f.stress.col(c) = sigma;
  }
  return f;
}

}  // namespace rccm
