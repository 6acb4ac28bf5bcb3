#include "rccm/base/memory.hpp"

#include "rccm/base/errors.hpp"

#include <cstdio>
#include <fstream>
#include <string>

namespace rccm {

double available_memory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  while (in >> key >> kb) {
    if (key == "MemAvailable:") return 1024 * kb;
    in.ignore(256, '\n');
  }
  return 1e18;
}

void require_memory(double bytes, const std::string& where, const std::string& what, const std::string& advice) {
  const double available = available_memory();
  if (bytes <= available) return;
  char text[160];
  std::snprintf(text, sizeof text, "%s needs about %.3g GB, the machine has %.3g GB available", what.c_str(),
                bytes / 1e9, available / 1e9);
  throw InputError(where + ": " + text + "; " + advice);
}

}  // namespace rccm
