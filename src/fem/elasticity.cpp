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

/// Quadrature points (xi, eta, weight) of a cell: T3 1 point (3 axisymmetric: the hoop
/// term varies), Q4 2 x 2 Gauss.
std::vector<Eigen::Vector3d> quadrature(int k, bool axisymmetric) {
  if (k == 3 && !axisymmetric) return {{1.0 / 3, 1.0 / 3, 0.5}};
  if (k == 3) return {{1.0 / 6, 1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}};
  const double g = 1.0 / std::sqrt(3.0);
  return {{-g, -g, 1}, {g, -g, 1}, {g, g, 1}, {-g, g, 1}};
}

Eigen::VectorXd cell_displacement(const Mesh& mesh, const std::vector<int>& cell, const Eigen::VectorXd& u) {
  Eigen::VectorXd ue(2 * cell.size());
  for (std::size_t a = 0; a < cell.size(); ++a) ue.segment<2>(2 * a) = u.segment<2>(mesh.dof(cell[a], 0));
  return ue;
}

}  // namespace

SparseMatrix assemble_stiffness(const Mesh& mesh, const std::vector<Material>& body_materials) {
  RCCM_VERIFY(mesh.dim == 2, "plane elasticity on a 2D mesh");
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::MatrixXd B;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const auto& cell = mesh.cells[c];
    const Eigen::Matrix4d& D = body_materials[mesh.cell_body[c]].D();
    const int k = static_cast<int>(cell.size());
    Eigen::MatrixXd Ke = Eigen::MatrixXd::Zero(2 * k, 2 * k);
    for (const Eigen::Vector3d& q : quadrature(k, mesh.axisymmetric)) {
      const double dV = strain_matrix(mesh, cell, q[0], q[1], B);
      Ke += B.transpose() * D * B * dV * q[2];  // K_e = int B^T D B dV
    }
    for (int a = 0; a < 2 * k; ++a)
      for (int b = 0; b < 2 * k; ++b)
        trip.emplace_back(mesh.dof(cell[a / 2], a % 2), mesh.dof(cell[b / 2], b % 2), Ke(a, b));
  }
  const int n = mesh.num_dofs();
  SparseMatrix K(n, n);
  K.setFromTriplets(trip.begin(), trip.end());
  return K;
}

CellFields cell_fields(const Mesh& mesh, const std::vector<Material>& body_materials, const Eigen::VectorXd& u) {
  CellFields f{Eigen::Matrix4Xd(4, mesh.cells.size()), Eigen::Matrix4Xd(4, mesh.cells.size())};
  Eigen::MatrixXd B;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
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
