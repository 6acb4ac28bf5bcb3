// The built-in 3D mesh source: a structured box [0, Lx] x [0, Ly] x [0, Lz] (shifted by the
// mesh origin) of H8 cells.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/mesh.hpp"

namespace rccm {

/// Structured box of nx x ny x nz H8 cells (nodes in VTK's hexahedron order: the face z- counter-
/// clockwise seen from z+, then the face z+), its boundary quads (counter-clockwise seen from
/// outside), and the node sets of its faces "left" (x = 0), "right", "bottom" (y = 0), "top",
/// "back" (z = 0), "front" (z = Lz), of its edges along z named as the rectangle's corners
/// ("bottom_left", "bottom_right", "top_left", "top_right": a box extruded from the rectangle
/// keeps its sets), of its vertices ("top_left_back": x = 0, y = Ly, z = 0; ...), "all" and
/// the box sets of `p.node_sets` (all in the unturned frame), finally turned by `p.rotation`
/// about `p.axis` through `p.origin` (the mesh's placement).
Mesh make_box(const MeshParams& p);

}  // namespace rccm
