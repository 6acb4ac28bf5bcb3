#include "rccm/interface/foundation.hpp"

#include <Eigen/Geometry>

namespace rccm {

Frame plane_frame(const Eigen::Vector3d& n) {
  Frame f;
  f.n = n;
  f.t1 = Eigen::Vector3d(n.y(), -n.x(), 0.0);
  if (n.z() != 0)  // 3D, a plane not containing z: t1 the unit horizontal tangent, or x when n is z
    f.t1 = f.t1.norm() > 1e-8 ? Eigen::Vector3d(f.t1.normalized()) : Eigen::Vector3d::UnitX();
  f.t2 = n.cross(f.t1);  // (t1, t2, n) right-handed
  return f;
}

Frame CircleFoundation::frame_at(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d out = radial(x).normalized();
  return plane_frame(inside ? Eigen::Vector3d(-out) : out);
}

double CircleFoundation::gap_at(const Eigen::Vector3d& x) const {
  const double r = radial(x).norm();
  return inside ? radius - r : r - radius;
}

}  // namespace rccm
