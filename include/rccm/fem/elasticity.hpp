// Linear elasticity of the bodies of a mesh in plane strain, plane stress or axisymmetry:
// element stiffness, global assembly, strains and stresses (docs/MODEL.md s1).
#pragma once

#include "rccm/fem/material.hpp"
#include "rccm/fem/mesh.hpp"
#include "rccm/la/sparse.hpp"

#include <Eigen/Core>

#include <vector>

namespace rccm {

/// Global stiffness K (DOFs mesh.dof(n, c)) with the material of each cell's body:
/// K = sum_e int B^T D B dV, dV = dA per unit thickness, or 2 pi r dA (axisymmetric), N/mm.
SparseMatrix assemble_stiffness(const Mesh& mesh, const std::vector<Material>& body_materials);

/// Strain and stress at each cell centre, a column per cell: 2D Voigt (xx, yy, xy, zz;
/// Material::complete), 3D Voigt3 (xx, yy, zz, yz, xz, xy).
struct CellFields {
  Eigen::MatrixXd strain, stress;
};
CellFields cell_fields(const Mesh& mesh, const std::vector<Material>& body_materials, const Eigen::VectorXd& u);

}  // namespace rccm
