// gmsh's side of a gmsh mesh source: what the program rccm-gmsh does with the gmsh C++ API
// (gmsh_mesh.hpp runs it). Only that program links gmsh: rccm itself starts without gmsh's
// ninety libraries (0.3 s of symbol binding at every start, 0.06 s without them).
#pragma once

#include "rccm/base/config.hpp"

#include <string>

namespace rccm {

/// Where a message about reading `p` is placed: the file (the dimension, asked while the
/// config is read), or the config's setting `where` and the file.
inline std::string gmsh_place(bool dimension_only, const MeshParams& p, const std::string& where) {
  return dimension_only ? p.file + ": " : where + ": " + p.file + ": ";
}

/// The answer to one request: "M" followed by the mesh of `p` (mesh_bytes.hpp), or by its
/// dimension ("2" or "3") when `dimension_only` (the file read, not meshed); or "E" followed
/// by the InputError message, placed at `where` and the file. Never throws.
std::string gmsh_answer(bool dimension_only, const MeshParams& p, const std::string& where);

}  // namespace rccm
