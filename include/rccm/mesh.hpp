// A 2D mesh of linear triangles (T3) or bilinear quadrilaterals (Q4) with named node sets.
#pragma once

#include "rccm/config.hpp"

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace rccm {

struct Mesh {
  ElementType element = ElementType::T3;
  std::vector<Eigen::Vector2d> nodes;          // mm
  std::vector<std::vector<int>> cells;         // counter-clockwise node lists
  std::vector<std::array<int, 2>> boundary;    // boundary edges (each in one cell only)
  std::map<std::string, std::vector<int>> node_sets;

  /// The nodes of a named set; throws InputError naming the known sets.
  const std::vector<int>& node_set(const std::string& name) const;

  /// Boundary edges whose two nodes both belong to `set` (sorted node ids).
  std::vector<std::array<int, 2>> edges_within(const std::vector<int>& set) const;

  /// Lumped edge measure per node of `set`: half the length of each adjacent edge in the set.
  std::vector<double> tributary_lengths(const std::vector<int>& set) const;
};

/// Where the point x of the unrotated rectangle lies after `p.rotation` about `p.origin`.
Eigen::Vector2d placed(const MeshParams& p, const Eigen::Vector2d& x);

/// Structured rectangle with sets "left", "right", "bottom", "top", the corners
/// "bottom_left", "bottom_right", "top_left", "top_right", "all", and the box sets of
/// `p.node_sets` (boxes in the unrotated frame), finally rotated by `p.rotation`.
/// T3 cells split each quad along (i,j)-(i+1,j+1) (BENCHMARKS.md B1).
Mesh make_rectangle(const MeshParams& p);

}  // namespace rccm
