// Replays the inputs the fuzzer found (tests/fuzz/corpus, and tests/fuzz/crashes: inputs that
// once broke rccm) through what the fuzz target does. In the RCCM_SANITIZE build this is
// also a sanitizer run over them.
#include "fuzz/untrusted_config.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

TEST_CASE("every input of the fuzzing corpus is refused as bad input or builds a model", "[config][fuzz]") {
  int inputs = 0, built = 0;
  for (const char* dir : {RCCM_SOURCE_DIR "/tests/fuzz/corpus", RCCM_SOURCE_DIR "/tests/fuzz/crashes"})
    for (const fs::directory_entry& f : fs::directory_iterator(dir)) {
      std::ifstream in(f.path(), std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      INFO(f.path().string());
      bool ok = false;
      REQUIRE_NOTHROW(ok = rccm::fuzz::build_untrusted_config(text));
      ++inputs;
      built += ok;
    }
  // The corpus reaches both sides: refusals and models built.
  CHECK(inputs > 100);
  CHECK(built > 0);
  CHECK(built < inputs);
}
