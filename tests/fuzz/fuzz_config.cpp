// libFuzzer target on the config loader and the mesh and model it describes (README
// "Sanitizers and fuzzing"). The corpus it found is in tests/fuzz/corpus, replayed by the
// test "every input of the fuzzing corpus is refused as bad input or builds a sound model".
#include "untrusted_config.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rccm::fuzz::build_untrusted_config(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
