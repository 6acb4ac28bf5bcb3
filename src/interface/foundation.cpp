#include "rccm/interface/foundation.hpp"

namespace rccm {

Frame FlatFoundation::frame_at(const Eigen::Vector3d&) const {
  Frame f;
  f.n = normal;
  f.t1 = Eigen::Vector3d(normal.y(), -normal.x(), 0.0);
  return f;
}

}  // namespace rccm
