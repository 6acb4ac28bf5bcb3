// The built-in mesh source: a structured rectangle of T3 or Q4 cells.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/mesh.hpp"

namespace rccm {

/// Structured rectangle with the node sets "left", "right", "bottom", "top", the corners
/// "bottom_left", "bottom_right", "top_left", "top_right", "all", and the box sets of
/// `p.node_sets` (boxes in the unrotated frame), finally rotated by `p.rotation` about
/// `p.origin` (the mesh's placement). T3 cells split each quad along (i,j)-(i+1,j+1)
/// (docs/BENCHMARKS.md B1). A box set may not take the name of a built-in set.
Mesh make_rectangle(const MeshParams& p);

/// The names of the node sets every rectangle has.
const std::vector<std::string>& rectangle_set_names();

}  // namespace rccm
