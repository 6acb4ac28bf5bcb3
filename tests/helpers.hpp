// Small helpers shared by the tests.
#pragma once

#include "rccm/config.hpp"

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace rccm::test {

/// Writes `text` to a temporary .cfg file and returns its path.
inline std::string write_temp_config(const std::string& text) {
  char name[] = "/tmp/rccm_test_XXXXXX.cfg";
  const int fd = mkstemps(name, 4);
  ::close(fd);
  std::ofstream(name) << text;
  return name;
}

inline Config config_from_text(const std::string& text, const std::vector<std::string>& overrides = {}) {
  const std::string path = write_temp_config(text);
  Config c = load_config(path, overrides);
  std::remove(path.c_str());
  return c;
}

}  // namespace rccm::test
