// The rigid foundation an interface faces, and the local frame it gives each contact node
// (docs/MODEL.md s2): today a flat one, given by its unit normal pointing into the body.
#pragma once

#include <Eigen/Core>

namespace rccm {

/// A contact pair's local frame: the normal n (from the foundation, or body B, into body A)
/// and the tangents; t2 is used in 3D only. Local component k < dim - 1 is along t_k, the
/// last one along n.
struct Frame {
  Eigen::Vector3d n = Eigen::Vector3d::UnitY();
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d t2 = Eigen::Vector3d::UnitZ();
  /// The axis of local component k of a `dim`-dimensional pair.
  const Eigen::Vector3d& axis(int k, int dim) const { return k == dim - 1 ? n : (k == 0 ? t1 : t2); }
};

struct FlatFoundation {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  // unit, into the body
  /// 2D: n and t = (n_y, -n_x) (t, n right-handed like x, y).
  Frame frame_at(const Eigen::Vector3d& x) const;
};

}  // namespace rccm
