#include "rccm/fem/elasticity.hpp"

#include "rccm/base/errors.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace rccm {

namespace {

/// A cell's shape functions at a point: their derivatives in x, y (, z) (dim x k), their
/// values N, det J, and (2D) the radius r = x of the point.
struct Shape {
  Eigen::MatrixXd dNx;
  Eigen::VectorXd N;
  double det = 0, r = 0;
};

/// 2D: at (xi, eta) of a cell. T3: xi, eta are area coordinates (dNx constant); Q4: the
/// reference square [-1, 1]^2.
Shape shape_2d(const Mesh& mesh, const std::vector<int>& cell, double xi, double eta) {
  const int k = static_cast<int>(cell.size());
  Eigen::MatrixXd dN(2, k);  // derivatives of the shape functions in the reference cell
  Shape s;
  s.N.resize(k);
  if (k == 3) {
    dN << -1, 1, 0, -1, 0, 1;
    s.N << 1 - xi - eta, xi, eta;
  } else {
    dN << -(1 - eta), (1 - eta), (1 + eta), -(1 + eta),  //
        -(1 - xi), -(1 + xi), (1 + xi), (1 - xi);
    dN *= 0.25;
    s.N << (1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta);
    s.N *= 0.25;
  }
  Eigen::MatrixXd X(k, 2);
  for (int a = 0; a < k; ++a) X.row(a) = mesh.nodes[cell[a]].head<2>().transpose();
  const Eigen::Matrix2d J = dN * X;
  s.det = J.determinant();
  RCCM_VERIFY(s.det > 0, "cell with non-positive Jacobian (clockwise or degenerate)");
  s.dNx = J.inverse() * dN;  // d/dx, d/dy
  s.r = s.N.dot(X.col(0));
  return s;
}

/// 3D: at r = (xi, eta, zeta) of a cell. T4 (k = 4): volume coordinates of the reference
/// tetrahedron (dNx constant); H8 (k = 8): the reference cube [-1, 1]^3.
Shape shape_3d(const Mesh& mesh, const std::vector<int>& cell, const Eigen::Vector3d& r) {
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
  Shape s;
  s.det = J.determinant();
  RCCM_VERIFY(s.det > 0, "3D cell with non-positive Jacobian (inverted or degenerate)");
  s.dNx = J.inverse() * dN;  // d/dx, d/dy, d/dz
  return s;
}

/// Strain-displacement matrix B (4 x 2k: xx, yy, xy, zz) at (xi, eta) of a cell, and the
/// volume weight of the point: det J (per unit thickness) or 2 pi r det J (axisymmetric,
/// where eps_zz = u_r / r).
double strain_matrix(const Mesh& mesh, const std::vector<int>& cell, double xi, double eta, Eigen::MatrixXd& B) {
  const int k = static_cast<int>(cell.size());
  const Shape s = shape_2d(mesh, cell, xi, eta);
  B.setZero(4, 2 * k);
  for (int a = 0; a < k; ++a) {
    B(0, 2 * a) = s.dNx(0, a);
    B(1, 2 * a + 1) = s.dNx(1, a);
    B(2, 2 * a) = s.dNx(1, a);
    B(2, 2 * a + 1) = s.dNx(0, a);
  }
  if (!mesh.axisymmetric) return s.det;
  for (int a = 0; a < k; ++a) B(3, 2 * a) = s.N[a] / s.r;  // eps_theta = u_r / r
  return 2 * M_PI * s.r * s.det;
}

/// 3D: strain-displacement matrix B (6 x 3k: xx, yy, zz, yz, xz, xy) at r of a cell, and det J.
double strain_matrix_3d(const Mesh& mesh, const std::vector<int>& cell, const Eigen::Vector3d& r, Eigen::MatrixXd& B) {
  const int k = static_cast<int>(cell.size());
  const Shape s = shape_3d(mesh, cell, r);
  const Eigen::MatrixXd& d = s.dNx;
  B.setZero(6, 3 * k);
  for (int a = 0; a < k; ++a) {
    B(0, 3 * a) = d(0, a);
    B(1, 3 * a + 1) = d(1, a);
    B(2, 3 * a + 2) = d(2, a);
    B(3, 3 * a + 1) = d(2, a), B(3, 3 * a + 2) = d(1, a);  // gamma_yz
    B(4, 3 * a) = d(2, a), B(4, 3 * a + 2) = d(0, a);      // gamma_xz
    B(5, 3 * a) = d(1, a), B(5, 3 * a + 1) = d(0, a);      // gamma_xy
  }
  return s.det;
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

/// The point where a cell's strain and stress are reported, in its reference coordinates: its
/// centre (T3 (1/3, 1/3), T4 (1/4, 1/4, 1/4), Q4 and H8 the origin).
Eigen::Vector3d centre(int dim, int k) {
  if (dim == 2) return k == 3 ? Eigen::Vector3d(1.0 / 3, 1.0 / 3, 0.0) : Eigen::Vector3d::Zero();
  return k == 4 ? Eigen::Vector3d::Constant(0.25) : Eigen::Vector3d::Zero();
}

/// Quadrature points (xi, eta, weight) of a cell: T3 1 point (3 axisymmetric: the hoop
/// term varies), Q4 2 x 2 Gauss.
std::vector<Eigen::Vector3d> quadrature(int k, bool axisymmetric) {
  if (k == 3 && !axisymmetric) return {{1.0 / 3, 1.0 / 3, 0.5}};
  if (k == 3) return {{1.0 / 6, 1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}};
  const double g = 1.0 / std::sqrt(3.0);
  return {{-g, -g, 1}, {g, -g, 1}, {g, g, 1}, {-g, g, 1}};
}

/// The measure of a reference cell, the sum of its quadrature weights (T3 1/2, Q4 4, T4 1/6, H8 8).
double reference_measure(int dim, int k) {
  double w = 0;
  if (dim == 3)
    for (const Eigen::Vector4d& q : quadrature_3d(k)) w += q[3];
  else
    for (const Eigen::Vector3d& q : quadrature(k, false)) w += q[2];
  return w;
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
      strain_matrix_3d(mesh, mesh.cells[c], centre(3, static_cast<int>(mesh.cells[c].size())), B);
      const Voigt3 eps = B * cell_displacement(mesh, mesh.cells[c], u);
      f.strain.col(c) = eps;
      f.stress.col(c) = body_materials[mesh.cell_body[c]].D3() * eps;
      continue;
    }
    const auto& cell = mesh.cells[c];
    const Eigen::Vector3d r = centre(2, static_cast<int>(cell.size()));
    strain_matrix(mesh, cell, r[0], r[1], B);
    Voigt eps = B * cell_displacement(mesh, cell, u), sigma;
    body_materials[mesh.cell_body[c]].complete(eps, sigma);
    f.strain.col(c) = eps;
    f.stress.col(c) = sigma;
  }
  return f;
}

SmallStrainCheck::SmallStrainCheck(const Mesh& mesh) : mesh_(mesh), first_(mesh.cells.size() + 1, 0) {
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) first_[c + 1] = first_[c] + static_cast<int>(mesh.cells[c].size());
  gradients_.setZero(mesh.dim + 1, first_.back());
  volume_.resize(static_cast<Eigen::Index>(mesh.cells.size()));
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const auto& cell = mesh.cells[c];
    const int k = static_cast<int>(cell.size());
    for (int n : cell) dof_.push_back(mesh.dof(n, 0));
    const Eigen::Vector3d r = centre(mesh.dim, k);
    const Shape s = mesh.dim == 3 ? shape_3d(mesh, cell, r) : shape_2d(mesh, cell, r[0], r[1]);
    gradients_.block(0, first_[c], mesh.dim, k) = s.dNx;
    double dV = s.det * reference_measure(mesh.dim, k);  // the cell's volume by its centre (exact for T3, T4 and parallelograms)
    if (mesh.dim == 2 && mesh.axisymmetric) {
      gradients_.block(2, first_[c], 1, k) = s.N.transpose() / s.r;  // the hoop u_r / r
      dV *= 2 * M_PI * s.r;
    }
    volume_[static_cast<Eigen::Index>(c)] = dV;
  }
}

DeformationExcess SmallStrainCheck::operator()(const Eigen::VectorXd& u, double limit) const {
  DeformationExcess e;
  const int dim = mesh_.dim;
  const std::size_t bodies = mesh_.body_names.size();
  std::vector<double> volume(bodies, 0.0), beyond(bodies, 0.0), largest(bodies, 0.0);
  std::vector<int> where(bodies, -1);
  for (std::size_t c = 0; c < mesh_.cells.size(); ++c) {
    const double dV = volume_[static_cast<Eigen::Index>(c)];
    const int body = mesh_.cell_body[c];
    volume[body] += dV;
    // H_ij = du_i / dx_j = sum_a u_a,i dN_a / dx_j; in 2D the zz place holds the hoop u_r / r.
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    for (int a = first_[c]; a < first_[c + 1]; ++a) {
      const double* g = gradients_.col(a).data();
      const double* ua = u.data() + dof_[a];
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) H(i, j) += ua[i] * g[j];
      if (dim == 2) H(2, 2) += g[2] * ua[0];
    }
    // |H|_2 <= |H|_F: the largest singular value only where it may pass the limit.
    if (H.norm() <= limit) continue;
    const double norm = H.operatorNorm();
    if (!(norm > limit)) continue;
    beyond[body] += dV;
    if (norm > largest[body]) largest[body] = norm, where[body] = static_cast<int>(c);
  }
  for (std::size_t b = 0; b < bodies; ++b)
    if (beyond[b] > e.fraction * volume[b])
      e.fraction = beyond[b] / volume[b], e.body = static_cast<int>(b), e.largest = largest[b], e.cell = where[b];
  return e;
}

}  // namespace rccm
