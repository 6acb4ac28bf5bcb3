// What the fuzz target and the corpus replay test do with one input: read any text as a
// config, then build the model it describes (mesh, node sets, interface, loads, stiffness,
// factorization, condensation). Bad input must end in InputError and nothing else: a crash,
// a sanitizer report, a hang or another exception is a bug.
#pragma once

#include "rccm/base/errors.hpp"
#include "rccm/fem/mesh_source.hpp"
#include "rccm/io/config_reader.hpp"
#include "rccm/model/model.hpp"

#include <algorithm>
#include <string>

namespace rccm::fuzz {

/// Whether the text was a good config whose model was built (false: refused as bad input).
inline bool build_untrusted_config(const std::string& text) {
  try {
    const Config cfg = parse_config(text, "fuzz.cfg");
    // Large meshes and interfaces are valid input but only slow the search down (a
    // 1000-node interface is a dense 2000 x 2000 flexibility).
    if (static_cast<double>(cfg.mesh.nx) * cfg.mesh.ny > 2000 || std::max(cfg.mesh.nx, cfg.mesh.ny) > 200) return false;
    if (!cfg.mesh.file.empty()) return false;  // the fuzzer explores the config, not gmsh
    const Model model(cfg, make_mesh(cfg));
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace rccm::fuzz
