// The gmsh mesh source: a .msh file (MSH 2.2 or 4.1) or a .geo file meshed at load, through
// the gmsh C++ API. Physical groups name everything: each Physical Surface is a body (its
// cells, T3 or Q4), each Physical Curve a node set along its line elements (in their order),
// each Physical Point a node set of one node; a body's name is also the node set of all its
// nodes. Two bodies glued by an interface have each their own curve along it.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/mesh.hpp"

#include <string>

namespace rccm {

/// Reads `p.file` (refined `p.refine` times; a .geo with `p.parameters` set). Throws
/// InputError "<where>: <file>: ..." naming the physical group of a mesh problem.
Mesh read_gmsh(const MeshParams& p, const std::string& where);

/// 3 when `p.file` has a Physical Volume (a 3D mesh), 2 otherwise; reads the file without
/// meshing it. Throws InputError "<file>: ..." when gmsh cannot read it.
int read_gmsh_dimension(const MeshParams& p);

/// While one lives, what gmsh answered is kept and given again for the same file (the same
/// contents), refinement and parameters, without starting gmsh: a sweep over other settings
/// reads its geometry once (make_sweep_cases, run_sweep). One at a time; the reads may come
/// from any thread.
class GmshReuse {
 public:
  GmshReuse();
  ~GmshReuse();
  GmshReuse(const GmshReuse&) = delete;
  GmshReuse& operator=(const GmshReuse&) = delete;
};

}  // namespace rccm
