// Where the mesh of a run comes from: a gmsh file (gmsh_mesh.hpp) or the built-in
// rectangle (rectangle_mesh.hpp), with the config's box node sets and placement.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/mesh.hpp"

#include <vector>

namespace rccm {

/// The mesh of `cfg.mesh`; throws InputError naming the config's setting, and the file and
/// physical group of a mesh problem.
Mesh make_mesh(const Config& cfg);

/// Adds a node set per box (nodes within [xmin, xmax] x [ymin, ymax], and [zmin, zmax] when the
/// box has 6 numbers, to round-off); a box may not take the name of an existing set.
void add_box_sets(Mesh& mesh, const std::vector<NodeSetDef>& boxes);

/// Turns the mesh by `p.rotation` degrees counter-clockwise (right-handed) about `p.axis`
/// through `p.origin` and records it as its placement.
void place(Mesh& mesh, const MeshParams& p);

}  // namespace rccm
