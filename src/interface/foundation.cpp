#include "rccm/interface/foundation.hpp"

namespace rccm {

Frame plane_frame(const Eigen::Vector3d& n) {
  Frame f;
  f.n = n;
  f.t1 = Eigen::Vector3d(n.y(), -n.x(), 0.0);
  return f;
}

Frame CircleFoundation::frame_at(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d out = (x - centre).normalized();
  return plane_frame(inside ? Eigen::Vector3d(-out) : out);
}

double CircleFoundation::gap_at(const Eigen::Vector3d& x) const {
  const double r = (x - centre).norm();
  return inside ? radius - r : r - radius;
}

}  // namespace rccm
