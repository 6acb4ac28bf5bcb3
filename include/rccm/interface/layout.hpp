// Local vectors of contact pairs (docs/MODEL.md s2): pair i's local components are stacked
// at dim i .. dim i + dim - 1 of an interface vector, the tangential ones first (one in 2D,
// two in 3D) and the normal one last. Every interface quantity (u, Rbar, Radh, y, the
// spring stiffness) uses this layout; code reads it through Layout, never as 2 i + 1.
//
// The dimension is a run-time value: one binary reads 2D and 3D configs, and the contact
// pairs' small vectors live on the stack (Eigen's fixed maximum size 3), so a 3D interface
// is "add elements, facets and the 3D projection" (docs/ARCHITECTURE.md).
#pragma once

#include <Eigen/Core>

namespace rccm {

/// A local vector of one contact pair (size dim), and a local matrix (dim x dim).
using LocalVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
using LocalMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;


struct Layout {
  int dim = 2;

  /// First component of pair i, and its normal component.
  Eigen::Index offset(int i) const { return Eigen::Index(dim) * i; }
  Eigen::Index normal(int i) const { return offset(i) + dim - 1; }
  int tangential_size() const { return dim - 1; }
  /// Pair i's local vector, and its tangential part, as a view into a stacked vector.
  template <class V>
  auto local(V&& v, int i) const {
    return v.segment(offset(i), dim);
  }
  template <class V>
  auto tangential(V&& v, int i) const {
    return v.segment(offset(i), dim - 1);
  }
  /// The number of pairs of a stacked vector of size m.
  int pairs(Eigen::Index m) const { return static_cast<int>(m / dim); }
};

}  // namespace rccm
