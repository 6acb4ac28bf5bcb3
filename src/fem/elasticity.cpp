#include "rccm/fem/elasticity.hpp"

#include "rccm/base/errors.hpp"

#include <Eigen/Dense>

#include <vector>

namespace rccm {

Eigen::Matrix3d hooke_matrix(const MaterialParams& m) {
  const double E = m.E, nu = m.nu;
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  if (m.hypothesis == Hypothesis::PlaneStrain) {
    const double f = E / ((1 + nu) * (1 - 2 * nu));
    D << 1 - nu, nu, 0, nu, 1 - nu, 0, 0, 0, (1 - 2 * nu) / 2;
    D *= f;
  } else {
    const double f = E / (1 - nu * nu);
    D << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
    D *= f;
  }
  return D;
}

namespace {

/// Strain-displacement matrix B (3 x 2k) and Jacobian determinant at (xi, eta) of a cell.
/// T3: xi, eta are area coordinates (B constant); Q4: the reference square [-1, 1]^2.
double strain_matrix(const Mesh& mesh, const std::vector<int>& cell, double xi, double eta,
                     Eigen::MatrixXd& B) {
  const int k = static_cast<int>(cell.size());
  Eigen::MatrixXd dN(2, k);  // derivatives of the shape functions in the reference cell
  if (k == 3) {
    dN << -1, 1, 0, -1, 0, 1;
  } else {
    dN << -(1 - eta), (1 - eta), (1 + eta), -(1 + eta),  //
        -(1 - xi), -(1 + xi), (1 + xi), (1 - xi);
    dN *= 0.25;
  }
  Eigen::MatrixXd X(k, 2);
  for (int a = 0; a < k; ++a) X.row(a) = mesh.nodes[cell[a]].head<2>().transpose();
  const Eigen::Matrix2d J = dN * X;
  const double det = J.determinant();
  RCCM_VERIFY(det > 0, "cell with non-positive Jacobian (clockwise or degenerate)");
  const Eigen::MatrixXd dNx = J.inverse() * dN;  // d/dx, d/dy
  B.setZero(3, 2 * k);
  for (int a = 0; a < k; ++a) {
    B(0, 2 * a) = dNx(0, a);
    B(1, 2 * a + 1) = dNx(1, a);
    B(2, 2 * a) = dNx(1, a);
    B(2, 2 * a + 1) = dNx(0, a);
  }
  return det;
}

/// Quadrature points (xi, eta, weight) of a cell: 1 point for T3, 2 x 2 Gauss for Q4.
std::vector<Eigen::Vector3d> quadrature(int k) {
  if (k == 3) return {{1.0 / 3, 1.0 / 3, 0.5}};
  const double g = 1.0 / std::sqrt(3.0);
  return {{-g, -g, 1}, {g, -g, 1}, {g, g, 1}, {-g, g, 1}};
}

}  // namespace

SparseMatrix assemble_stiffness(const Mesh& mesh, const MaterialParams& m) {
  RCCM_VERIFY(mesh.dim == 2, "plane elasticity on a 2D mesh");
  const Eigen::Matrix3d D = hooke_matrix(m);
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::MatrixXd B;
  for (const auto& cell : mesh.cells) {
    const int k = static_cast<int>(cell.size());
    Eigen::MatrixXd Ke = Eigen::MatrixXd::Zero(2 * k, 2 * k);
    for (const Eigen::Vector3d& q : quadrature(k)) {
      const double det = strain_matrix(mesh, cell, q[0], q[1], B);
      Ke += B.transpose() * D * B * det * q[2];  // K_e = int B^T D B dA
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

Eigen::Matrix3Xd cell_strains(const Mesh& mesh, const Eigen::VectorXd& u) {
  Eigen::Matrix3Xd eps(3, mesh.cells.size());
  Eigen::MatrixXd B;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const auto& cell = mesh.cells[c];
    const int k = static_cast<int>(cell.size());
    const double centre = k == 3 ? 1.0 / 3 : 0.0;
    strain_matrix(mesh, cell, centre, centre, B);
    Eigen::VectorXd ue(2 * k);
    for (int a = 0; a < k; ++a) ue.segment<2>(2 * a) = u.segment<2>(mesh.dof(cell[a], 0));
    eps.col(c) = B * ue;
  }
  return eps;
}

}  // namespace rccm
