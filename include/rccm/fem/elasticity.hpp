// Isotropic linear elasticity in plane strain or plane stress: element stiffness,
// global assembly, strains and stresses (docs/MODEL.md s1).
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/mesh.hpp"
#include "rccm/la/sparse.hpp"

#include <Eigen/Core>

namespace rccm {

/// Hooke matrix D (Voigt order xx, yy, xy with engineering shear), MPa.
Eigen::Matrix3d hooke_matrix(const MaterialParams& m);

/// Global stiffness K (DOFs mesh.dof(n, c)), N/mm per unit thickness.
SparseMatrix assemble_stiffness(const Mesh& mesh, const MaterialParams& m);

/// Strain (xx, yy, xy engineering) at each cell centre for nodal displacements u.
Eigen::Matrix3Xd cell_strains(const Mesh& mesh, const Eigen::VectorXd& u);

}  // namespace rccm
