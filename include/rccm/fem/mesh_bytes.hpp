// A mesh as bytes, from the gmsh process that read it (rccm-gmsh) to the caller: numbers as
// the machine holds them (both programs are built together, for this machine), strings and
// lists after their length.
#pragma once

#include "rccm/fem/mesh.hpp"

#include <string>

namespace rccm {

/// What rccm and rccm-gmsh must share to talk: the version and this format's number (a
/// program of another build answers that it is one).
inline std::string mesh_bytes_protocol() { return std::string(RCCM_VERSION_STRING) + "/2"; }

std::string pack_mesh(const Mesh& m);
/// The mesh of `bytes`; RCCM_VERIFY fails on bytes cut short or too long.
Mesh unpack_mesh(const std::string& bytes);

}  // namespace rccm
