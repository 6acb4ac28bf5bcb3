// An order of points in which every half, quarter, ... of the index range is a compact
// cluster in space: recursive coordinate bisection. A hierarchical matrix (la/hodlr.hpp)
// bisects its index range; over an interface surface in this order its off-diagonal blocks
// couple compact patches instead of thin strips (the rows of a lexicographic grid), and keep
// lower ranks.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace rccm {

/// The indices of `points` in recursive coordinate bisection order: the set is split at the
/// median of its longest extent into halves of floor(n / 2) and ceil(n / 2) points (the
/// HODLR's bisection), each half ordered alike. Ties are broken by index (deterministic).
std::vector<int> bisection_order(const std::vector<Eigen::Vector3d>& points);

}  // namespace rccm
