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

/// How far the bodies are from small strains, the hypothesis of linear elasticity: the
/// displacement gradient H = grad u at each cell's centre (3 x 3; in 2D the zz place holds an
/// axisymmetric body's hoop u_r / r), measured by its largest singular value |H|_2 (a rigid
/// rotation by theta: 2 sin(theta / 2); a uniform stretch by e: |e|).
struct DeformationExcess {
  double fraction = 0;  // the largest share of a body's volume (each cell at its centre) where |H|_2 > limit
  int body = -1;        // that body (-1: none exceeds the limit)
  double largest = 0;   // the largest |H|_2 in that body (0: none)
  int cell = -1;        // the cell where it is
};

/// Measures a mesh's displacements as a run goes (Recorder::note_deformation): the cells'
/// shape gradients at their centres are computed once, a check then costs a few products per cell.
class SmallStrainCheck {
 public:
  explicit SmallStrainCheck(const Mesh& mesh);
  DeformationExcess operator()(const Eigen::VectorXd& u, double limit) const;

 private:
  const Mesh& mesh_;
  std::vector<int> first_;     // cell c's nodes are columns first_[c] .. first_[c + 1] - 1 of gradients_
  std::vector<int> dof_;       // the first DOF of each of those nodes
  Eigen::MatrixXd gradients_;  // dN_a/dx_j in rows 0 .. dim - 1; 2D: N_a / r in row 2 (axisymmetric, else 0)
  Eigen::VectorXd volume_;     // of each cell
};

}  // namespace rccm
