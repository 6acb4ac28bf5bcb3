// What the fuzz target and the corpus replay test do with one input: read any text as a
// config, then build the model it describes (mesh, node sets, interface, loads, stiffness,
// factorization, condensation). Bad input must end in InputError and nothing else: a crash,
// a sanitizer report, a hang or another exception is a bug.
#pragma once

#include "rccm/config.hpp"
#include "rccm/errors.hpp"
#include "rccm/model.hpp"

#include <string>

namespace rccm::fuzz {

/// Whether the text was a good config whose model was built (false: refused as bad input).
inline bool build_untrusted_config(const std::string& text) {
  try {
    const Config cfg = parse_config(text, "fuzz.cfg");
    // Large meshes are valid input but only slow the search down.
    if (static_cast<double>(cfg.mesh.nx) * cfg.mesh.ny > 2000) return false;
    const Model model(cfg);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace rccm::fuzz
