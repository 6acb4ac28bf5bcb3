#include "rccm/la/bisection_order.hpp"

#include <algorithm>
#include <numeric>

namespace rccm {

namespace {

void bisect(std::vector<int>::iterator begin, std::vector<int>::iterator end, const std::vector<Eigen::Vector3d>& x) {
  if (end - begin < 2) return;
  Eigen::Vector3d lo = x[*begin], hi = lo;
  for (auto it = begin; it != end; ++it) lo = lo.cwiseMin(x[*it]), hi = hi.cwiseMax(x[*it]);
  Eigen::Index axis = 0;
  (hi - lo).maxCoeff(&axis);
  const auto mid = begin + (end - begin) / 2;
  std::nth_element(begin, mid, end, [&](int a, int b) { return x[a][axis] < x[b][axis] || (x[a][axis] == x[b][axis] && a < b); });
  bisect(begin, mid, x);
  bisect(mid, end, x);
}

}  // namespace

std::vector<int> bisection_order(const std::vector<Eigen::Vector3d>& points) {
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  bisect(order.begin(), order.end(), points);
  return order;
}

}  // namespace rccm
