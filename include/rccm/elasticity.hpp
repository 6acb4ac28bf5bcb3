// Isotropic linear elasticity in plane strain or plane stress: element stiffness,
// global assembly, strains and stresses (MODEL.md s1).
#pragma once

#include "rccm/config.hpp"
#include "rccm/mesh.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rccm {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Hooke matrix D (Voigt order xx, yy, xy with engineering shear), MPa.
Eigen::Matrix3d hooke_matrix(const MaterialParams& m);

/// Global stiffness K (2 DOFs per node: x = 2n, y = 2n+1), N/mm per unit thickness.
SparseMatrix assemble_stiffness(const Mesh& mesh, const MaterialParams& m);

/// Strain (xx, yy, xy engineering) at each cell centre for nodal displacements u.
Eigen::Matrix3Xd cell_strains(const Mesh& mesh, const Eigen::VectorXd& u);

}  // namespace rccm
