// The contact nodes facing the rigid foundation: tributary lengths, local frames and the
// operator P from global displacements to local (t, n) components (MODEL.md s2).
#pragma once

#include "rccm/config.hpp"
#include "rccm/elasticity.hpp"
#include "rccm/mesh.hpp"

#include <Eigen/Core>

#include <vector>

namespace rccm {

struct Interface {
  std::vector<int> nodes;  // mesh node of each contact node i
  Eigen::VectorXd a;       // tributary length a_i, mm
  Eigen::Vector2d n;       // foundation normal (into the body)
  Eigen::Vector2d t;       // tangent, t = (n_y, -n_x)
  double Cn = 0, Ct = 0;   // MPa/mm
  SparseMatrix P;          // 2 nc x 2 N: rows 2i (t) and 2i+1 (n) of node i

  int size() const { return static_cast<int>(nodes.size()); }

  /// Interface springs at beta = 1 as a global matrix, P^T diag(a_i Ct, a_i Cn) P (MODEL.md s4).
  SparseMatrix initial_springs() const;

  /// P^T diag(a_i Ct w_t,i, a_i Cn w_n,i) P: springs of per-node weights (w = beta^2: the
  /// adhesive springs at beta).
  SparseMatrix springs(const Eigen::VectorXd& weight_t, const Eigen::VectorXd& weight_n) const;
};

/// Builds the interface on the node set `p.boundary`; throws InputError if it has no edge.
Interface make_interface(const Mesh& mesh, const InterfaceParams& p);

}  // namespace rccm
