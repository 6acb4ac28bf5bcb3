// libFuzzer target: any text as a config, then the model it describes (mesh, node sets,
// interface, loads, stiffness, factorization). Bad input must end in InputError, nothing
// else: a crash, a sanitizer report, a hang or another exception is a bug.
// README "Sanitizers and fuzzing"; the corpus it found is in tests/fuzz/corpus and replayed
// by the test "the fuzzing corpus is refused or built cleanly".
#include "rccm/config.hpp"
#include "rccm/errors.hpp"
#include "rccm/model.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const rccm::Config cfg = rccm::parse_config(text, "fuzz.cfg");
    // Large meshes are valid input but only slow the search down.
    if (static_cast<double>(cfg.mesh.nx) * cfg.mesh.ny > 2000) return 0;
    const rccm::Model model(cfg);
  } catch (const rccm::InputError&) {
  }
  return 0;
}
