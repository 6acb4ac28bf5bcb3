// Checks of a 3D mesh's stiffness shared by the H8 (box) and T4/H8 (gmsh) tests: the six
// rigid motions are free, and a uniform strain u = G x (the patch test) leaves the interior
// nodes without force and gives Hooke's strain and stress in every cell.
#pragma once

#include "rccm/fem/elasticity.hpp"
#include "rccm/fem/material.hpp"
#include "rccm/fem/mesh.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <catch2/catch.hpp>

namespace rccm::test {

/// Runs the checks on `m` (one isotropic material E, nu); returns the number of interior nodes.
inline int check_rigid_motions_and_patch(const Mesh& m, double E, double nu) {
  MaterialParams p;
  p.E = E, p.nu = nu;
  const std::vector<Material> materials(m.body_names.size(), Material(p));
  const SparseMatrix K = assemble_stiffness(m, materials);
  CHECK((Eigen::MatrixXd(K) - Eigen::MatrixXd(K).transpose()).norm() <= 1e-12 * Eigen::MatrixXd(K).norm());
  for (int mode = 0; mode < 6; ++mode) {  // three translations, three (small) rotations
    Eigen::VectorXd u(m.num_dofs());
    for (int n = 0; n < m.num_nodes(); ++n)
      u.segment<3>(m.dof(n, 0)) = mode < 3 ? Eigen::Vector3d(Eigen::Vector3d::Unit(mode))
                                           : Eigen::Vector3d(Eigen::Vector3d::Unit(mode - 3).cross(m.nodes[n]));
    CHECK((K * u).norm() <= 1e-10 * K.norm() * u.norm());
  }
  Eigen::Matrix3d G;
  G << 1e-3, 2e-4, -1e-4, 3e-4, -5e-4, 6e-4, 0.0, 1e-4, 2e-3;
  Eigen::VectorXd u(m.num_dofs());
  for (int n = 0; n < m.num_nodes(); ++n) u.segment<3>(m.dof(n, 0)) = G * m.nodes[n];
  const Eigen::VectorXd f = K * u;
  std::vector<char> on_boundary(m.num_nodes(), 0);
  for (const auto& facet : m.facets)
    for (int n : facet) on_boundary[n] = 1;
  int interior = 0;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (!on_boundary[n]) {
      CHECK(f.segment<3>(m.dof(n, 0)).norm() <= 1e-12 * f.norm());
      ++interior;
    }
  const CellFields c = cell_fields(m, materials, u);
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const Eigen::Matrix3d sigma = lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
  Voigt3 eps_v, sigma_v;
  eps_v << eps(0, 0), eps(1, 1), eps(2, 2), 2 * eps(1, 2), 2 * eps(0, 2), 2 * eps(0, 1);
  sigma_v << sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(1, 2), sigma(0, 2), sigma(0, 1);
  for (Eigen::Index k = 0; k < c.strain.cols(); ++k) {
    CHECK((c.strain.col(k) - eps_v).norm() <= 1e-13 * eps_v.norm());
    CHECK((c.stress.col(k) - sigma_v).norm() <= 1e-11 * sigma_v.norm());
  }
  return interior;
}

}  // namespace rccm::test
