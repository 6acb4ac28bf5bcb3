// Recursive coordinate bisection order (la/bisection_order): a permutation whose aligned
// halves, quarters, ... are compact clusters split by planes.
#include "rccm/la/bisection_order.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

using namespace rccm;

TEST_CASE("bisection order: a permutation whose every bisection is split by a plane into compact halves",
          "[bisection]") {
  // A 16 x 16 grid in the x-z plane at y = 1, listed row by row (the node order of a box face).
  const int n = 16;
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) x.emplace_back(0.5 * i, 1.0, 0.5 * k);
  const std::vector<int> order = bisection_order(x);
  REQUIRE(std::set<int>(order.begin(), order.end()).size() == x.size());
  REQUIRE(*std::min_element(order.begin(), order.end()) == 0);
  REQUIRE(*std::max_element(order.begin(), order.end()) == int(x.size()) - 1);
  CHECK(bisection_order(x) == order);  // deterministic
  // Every aligned block of 2^j points is a (2^a x 2^b) sub-grid with |a - b| <= 1 (a square
  // or two squares side by side, not a strip of rows), and its halves lie on either side of
  // a plane x = c or z = c.
  for (int size = 2; size <= n * n; size *= 2)
    for (int first = 0; first < n * n; first += size) {
      Eigen::Vector3d lo = x[order[first]], hi = lo;
      for (int j = first; j < first + size; ++j) lo = lo.cwiseMin(x[order[j]]), hi = hi.cwiseMax(x[order[j]]);
      const int nx = int(std::lround((hi.x() - lo.x()) / 0.5)) + 1, nz = int(std::lround((hi.z() - lo.z()) / 0.5)) + 1;
      INFO("block of " << size << " from " << first);
      CHECK(nx * nz == size);
      CHECK(std::max(nx, nz) <= 2 * std::min(nx, nz));
      CHECK(hi.y() == lo.y());
      const int half = size / 2;
      bool split = false;
      for (int axis : {0, 2}) {
        double first_max = -1e300, second_min = 1e300;
        for (int j = first; j < first + half; ++j) first_max = std::max(first_max, x[order[j]][axis]);
        for (int j = first + half; j < first + size; ++j) second_min = std::min(second_min, x[order[j]][axis]);
        split = split || first_max < second_min;
      }
      CHECK(split);
    }
  // Odd counts: the halves hold floor(n / 2) and ceil(n / 2) points (the HODLR's bisection).
  const std::vector<Eigen::Vector3d> line{{0, 0, 0}, {3, 0, 0}, {1, 0, 0}, {4, 0, 0}, {2, 0, 0}};
  CHECK(bisection_order(line) == std::vector<int>{0, 2, 4, 1, 3});
}
