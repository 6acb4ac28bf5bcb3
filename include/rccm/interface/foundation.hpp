// The rigid foundation an interface faces, and the local frame and initial gap it gives each
// contact node (docs/MODEL.md s2): a line, given by its unit normal pointing into the body,
// or a circle with the body inside it (a hole) or outside it (a cylinder); in 3D a plane, a
// sphere, or a cylinder about an axis.
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

/// The frame of unit normal n: t1 = (n_y, -n_x, 0) (2D: t, n right-handed like x, y), made unit,
/// or x when n is along z; t2 = n x t1 (3D: t1, t2, n right-handed).
Frame plane_frame(const Eigen::Vector3d& n);

struct FlatFoundation {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  // unit, into the body
  Frame frame_at(const Eigen::Vector3d&) const { return plane_frame(normal); }
};

struct CircleFoundation {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0;
  bool inside = true;  // the body inside the circle: n points to the centre (the axis)
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();  // 3D: a cylinder's unit axis through the centre; zero: a sphere (2D: the circle)
  /// From the centre (a cylinder: the nearest point of its axis) to x.
  Eigen::Vector3d radial(const Eigen::Vector3d& x) const { return (x - centre) - (x - centre).dot(axis) * axis; }
  /// The radial frame at x: n from the circle into the body.
  Frame frame_at(const Eigen::Vector3d& x) const;
  /// The distance from the circle to x along n (negative: x lies in the rigid part).
  double gap_at(const Eigen::Vector3d& x) const;
};

}  // namespace rccm
